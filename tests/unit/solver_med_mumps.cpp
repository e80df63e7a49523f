// One executable that reads a MED file (MED-fichier over OpenMPI's HDF5) and factorises with
// MUMPS (the parallel build, on the same OpenMPI, initialised lazily): both must work side by
// side, before and after each other.
#include <gtest/gtest.h>

#include "fe/Result.hpp"
#include "fe_test_support.hpp"
#include "med_io/MedReader.hpp"

using namespace ma;
using namespace fetest;

TEST(SolverMedMumps, ReadMedThenSolveWithMumpsThenReadAgain) {
    msg().setEcho(false);
    const std::string path = std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv511a.mmed";
    std::shared_ptr<Mesh> mesh = med::readMesh(path);
    mesh->name = "MAILLAG";
    ASSERT_GT(mesh->nodeCount(), 0);
    auto model = affeModele(mesh, "D_PLAN", {"SURF"});
    auto mat = material(model, 100e6, 0.3);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LG"});
    set(d, "DX", 0.0), set(d, "DY", 0.0);
    auto& f = kw.addOccurrence("FORCE_INTERNE");
    set(f, "TOUT", std::string("OUI"));
    set(f, "FY", -7800.0 * 9.81);
    auto load = run("AFFE_CHAR_MECA", kw, "CHAR");
    std::shared_ptr<NodalField> u[2];
    int i = 0;
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        KeywordSet s;
        set(s, "MODELE", model);
        set(s, "CHAM_MATER", mat);
        set(s.addOccurrence("EXCIT"), "CHARGE", load);
        set(s.addOccurrence("SOLVEUR"), "METHODE", std::string(method));
        auto res = std::dynamic_pointer_cast<Result>(run("MECA_STATIQUE", s, "RESU"));
        u[i++] = res->steps[0].nodal("DEPL");
    }
    double scale = 0;
    for (double v : u[0]->values) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    for (size_t k = 0; k < u[0]->values.size(); ++k) EXPECT_NEAR(u[0]->values[k], u[1]->values[k], 1e-11 * scale);
    // HDF5/MED still usable after MUMPS ran.
    auto again = med::readMesh(path);
    EXPECT_EQ(again->nodeCount(), mesh->nodeCount());
    EXPECT_EQ(again->cellCount(), mesh->cellCount());
}
