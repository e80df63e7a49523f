// resplit_layer: re-splits a layer of prisms cut into TETRA4 so that it conforms (scenes/LayerResplit.hpp).
//
//   resplit_layer in.med out.med
//
// code_aster's ssnv511h.mmed cuts 34 of its inner quadrangles along different diagonals on their two
// sides (LIRE_MAILLAGE's alarm MAILLAGE_NON_CONFORME, docs/mesh.md "Conformity"); the same nodes
// re-split by one rule give the conforming mesh on which the scene's answer is exact.
#include <cstdio>
#include <exception>

#include "med_io/MedReader.hpp"
#include "med_io/MedWriter.hpp"
#include "mesh/MeshConformity.hpp"
#include "scenes/LayerResplit.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: resplit_layer in.med out.med\n");
        return 2;
    }
    try {
        const auto names = ma::med::meshNames(argv[1]);
        const auto layer = ma::med::readMesh(argv[1]);
        const auto mesh = ma::resplitPrismLayer(*layer);
        const auto before = ma::meshConformity(*layer), after = ma::meshConformity(*mesh);
        ma::med::MedWriter writer(argv[2], false);
        writer.writeMesh(*mesh, names.front());
        writer.commit();
        std::printf("%s: mesh %s, %d nodes, %d cells; faces inside the domain seen by one cell: %d before, %d after\n",
                    argv[2], names.front().c_str(), mesh->nodeCount(), mesh->cellCount(), before.overlappingFaces,
                    after.overlappingFaces);
        return after.overlappingFaces == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "resplit_layer: %s\n", e.what());
        return 1;
    }
}
