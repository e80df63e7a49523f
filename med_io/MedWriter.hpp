#pragma once
// Writing meshes and result fields to MED files, code_aster conventions (docs/med.md).
// The file is written under a temporary name and renamed by commit(): a failure never leaves a
// half-written file (appending works on a copy of the existing file).
#include <memory>
#include <string>

#include "fields/Fields.hpp"
#include "mesh/Mesh.hpp"

namespace ma::med {

// code_aster's MED field name: result name padded with '_' to 8 characters + field name,
// e.g. ("UTOT1", "DEPL") -> "UTOT1___DEPL".
std::string resultFieldName(const std::string& resultName, const std::string& fieldName);

class MedWriter {
public:
    // append=false: a new file replaces `path` at commit(); append=true: adds to the existing file
    // (created when absent).
    MedWriter(const std::string& path, bool append);
    ~MedWriter();
    MedWriter(const MedWriter&) = delete;
    MedWriter& operator=(const MedWriter&) = delete;

    // Writes the mesh with its groups (as families) under `meshName`. When the file already holds
    // a mesh of that name with the same numbers of nodes and cells, nothing is written (several
    // IMPR_RESU to one file) and false is returned; a different mesh of the same name is a
    // UserError.
    bool writeMesh(const Mesh& mesh, const std::string& meshName);

    // A nodal field at step (numdt, numit, dt) on the mesh written as `meshName`: components that
    // at least one node carries; nodes carrying none are left out through a MED profile; a
    // component a written node does not carry is written as 0 (docs/med.md).
    void writeNodalField(const std::string& fieldName, const std::string& meshName, const NodalField& field, int numdt,
                         int numit, double dt);

    // A field at integration points (ELGA) with its MED localisations: the elements of one cell
    // type that share the same reference points share one localisation (and a profile when
    // they are not all the cells of that type). Returns the number of elements that could not be
    // written (cell types without a reference element); an alarm names them.
    int writeGaussField(const std::string& fieldName, const std::string& meshName, const GaussField& field, int numdt,
                        int numit, double dt);
    // An ELNO field (GaussField::atNodes): the values at each cell's nodes on MED_NODE_ELEMENT, in
    // MED node order, one block per cell type (with a profile when not every cell of it).
    void writeNodeElementField(const std::string& fieldName, const std::string& meshName, const GaussField& field,
                               int numdt, int numit, double dt);

    // Closes the file and moves it to its final name.
    void commit();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ma::med
