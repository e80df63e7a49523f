// ssnv511_mesh: writes an ssnv511-family mesh with N divisions per side as a MED file.
//
//   ssnv511_mesh --type quad4|tria3|hexa8|tetra4 --n N -o out.med
//                [--bounds XMIN XMAX YMIN YMAX] [--zbounds ZMIN ZMAX] [--layers K]
//                [--offset OX OY] [--name MESH] [--polar]
//
// Groups and conventions are those of ../shared/astest (docs/med.md): 2D SURF + LB/LD/LH/LG
// (SEG2, counter-clockwise); 3D VOLU + ENV (outward skin), HEXA8 also SD (x=XMAX) and SG (x=XMIN).
// --offset moves the interior grid lines by OX, OY cell sizes (|O| < 1) so that the interfaces
// x=0, y=0 and the junction point are not at cell centres / on grid lines.
// --polar reads x as the radius and y as the angle in degrees (2D, and each HEXA8/TETRA4 layer
// about the z axis): XMIN <= r <= XMAX, YMIN <= theta <= YMAX, a ring sector whose arcs are LG
// (r = XMIN) and LD (r = XMAX), its straight sides LB (theta = YMIN) and LH (theta = YMAX).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/Error.hpp"
#include "med_io/MedWriter.hpp"
#include "scenes/Ssnv511Mesh.hpp"

namespace {

[[noreturn]] void usage(const char* why) {
    std::fprintf(stderr,
                 "ssnv511_mesh: %s\nusage: ssnv511_mesh --type quad4|tria3|hexa8|tetra4 --n N -o out.med\n"
                 "       [--bounds XMIN XMAX YMIN YMAX] [--zbounds ZMIN ZMAX] [--layers K] [--offset OX OY] [--name "
                 "MESH] [--polar]\n",
                 why);
    std::exit(2);
}

// The ring sector of --polar: (r, theta in degrees) -> (x, y), z kept.
void toPolar(ma::Mesh& mesh) {
    for (auto& x : mesh.coords) {
        const double r = x[0], theta = x[1] * M_PI / 180.0;
        x[0] = r * std::cos(theta), x[1] = r * std::sin(theta);
    }
}

double number(int& i, int argc, char** argv) {
    if (i + 1 >= argc) usage("missing value");
    char* end = nullptr;
    const double v = std::strtod(argv[++i], &end);
    if (!end || *end) usage((std::string("not a number: ") + argv[i]).c_str());
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    ma::Ssnv511MeshOptions opt;
    std::string out, meshName = "MAILLAGE";
    bool typeGiven = false, polar = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--type") {
            if (i + 1 >= argc || !ma::ssnv511KindFromName(argv[++i], opt.kind)) usage("unknown --type");
            typeGiven = true;
        } else if (a == "--n") {
            const double n = number(i, argc, argv);
            if (n != int(n)) usage("--n must be an integer");
            opt.divisions = int(n);
        } else if (a == "-o") {
            if (i + 1 >= argc) usage("missing file name after -o");
            out = argv[++i];
        } else if (a == "--bounds") {
            opt.xmin = number(i, argc, argv), opt.xmax = number(i, argc, argv);
            opt.ymin = number(i, argc, argv), opt.ymax = number(i, argc, argv);
        } else if (a == "--zbounds") {
            opt.zmin = number(i, argc, argv), opt.zmax = number(i, argc, argv);
        } else if (a == "--layers") {  // HEXA8: K cells in z (default 1)
            const double k = number(i, argc, argv);
            if (k != int(k)) usage("--layers must be an integer");
            opt.layers = int(k);
        } else if (a == "--offset") {
            opt.offsetX = number(i, argc, argv), opt.offsetY = number(i, argc, argv);
        } else if (a == "--name") {
            if (i + 1 >= argc) usage("missing mesh name");
            meshName = argv[++i];
        } else if (a == "--polar") {
            polar = true;
        } else if (a == "-h" || a == "--help") {
            usage("help");
        } else {
            usage(("unknown argument " + a).c_str());
        }
    }
    if (!typeGiven || out.empty()) usage("--type and -o are required");
    try {
        const auto t0 = std::chrono::steady_clock::now();
        if (polar && opt.xmin <= 0) usage("--polar needs a positive inner radius XMIN");
        auto mesh = ma::buildSsnv511Mesh(opt);
        if (polar) toPolar(*mesh);
        ma::med::MedWriter writer(out, false);
        writer.writeMesh(*mesh, meshName);
        writer.commit();
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("%s: mesh %s, %d nodes, %d cells (%.2f s)\n", out.c_str(), meshName.c_str(), mesh->nodeCount(),
                    mesh->cellCount(), s);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssnv511_mesh: %s\n", e.what());
        return 1;
    }
    return 0;
}
