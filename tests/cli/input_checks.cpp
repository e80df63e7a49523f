// Input that used to run without a word and give a wrong answer (issue 29, items 2, 3 and the
// coordinates of item 8): a JONCTION point on its master interface, outside the mesh or with the
// wrong number of coordinates; non-finite or out-of-range coordinates; a duplicated cell or a cell
// with a repeated node; a group the mesh does not have. Each is refused (or, where code_aster only
// warns, reported as its alarm) through the binary, on meshes written by the test; the valid
// counterpart still runs. The JONCTION cases run code_aster's ssnv511a.comm, read from
// ../shared/astest, with its POINT replaced.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "med_io/MedWriter.hpp"
#include "parser_run.hpp"
#include "scenes/Ssnv511Mesh.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

std::string ssnv511a() {
    std::ifstream in(std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv511a.comm");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// ssnv511a.comm with each `from` replaced by its `to` (the test fails when one is absent) and a MED
// result written at the end (IMPR_RESU on unit 80), so that a run which stops leaves it unwritten.
std::string ssnv511aWith(const std::vector<std::pair<std::string, std::string>>& edits) {
    std::string text = ssnv511a();
    for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    const auto fin = text.rfind("FIN()");
    return text.substr(0, fin) + "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=UTOT1))\n" + text.substr(fin);
}

// FISS2's POINT (0, 5) replaced.
std::string ssnv511aWithPoint(const std::string& point) { return ssnv511aWith({{"POINT=(0,5)", point}}); }

void writeMesh(const ma::Mesh& mesh, const fs::path& path) {
    ma::med::MedWriter w(path.string(), false);
    w.writeMesh(mesh, "MAILLAGE");
    w.commit();
}

std::shared_ptr<ma::Mesh> quad4(int n, double offsetY = 0.0, double scale = 1.0) {
    ma::Ssnv511MeshOptions o;
    o.divisions = n;
    o.offsetY = offsetY;
    o.xmin = o.ymin = -5 * scale;
    o.xmax = o.ymax = 5 * scale;
    return ma::buildSsnv511Mesh(o);
}

// Runs `comm` as t.comm on `mesh` (mesh.med on unit 20, the MED result t.rmed on unit 80).
RunResult runOn(const ma::Mesh& mesh, const std::string& comm) {
    const auto dir = freshDir();
    writeMesh(mesh, dir / "mesh.med");
    writeText(dir / "t.comm", comm);
    writeText(dir / "t.export", "F comm t.comm D 1\nF mmed mesh.med D 20\nF rmed t.rmed R 80\n");
    return runMiniaster(dir, "t.export");
}

// The run stopped at `command` on line `line` of t.comm with a message holding every part of
// `parts`: exit 1, no result file.
void expectRefused(const RunResult& r, const std::string& command, int line, const std::vector<std::string>& parts) {
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string head = "<F> <ERROR> " + command + " (t.comm, line " + std::to_string(line) + "): ";
    const auto at = r.output.find(head);
    ASSERT_NE(at, std::string::npos) << head << "\n" << r.output;
    const std::string paragraph = r.output.substr(at, r.output.find('\n', at) - at);
    for (const auto& p : parts) EXPECT_NE(paragraph.find(p), std::string::npos) << p << "\nin: " << paragraph;
    EXPECT_FALSE(r.exists("out/t.rmed")) << "no result after an error";
    EXPECT_NE(r.file("out/t.mess").find(paragraph), std::string::npos) << "the .mess keeps the diagnosis";
}

}  // namespace

// The interface y = 0 between node rows (N = 4, rows moved by half a cell): the node nearest to
// POINT is off the interface, so the side used to be taken from it (NOOK, DX -0.25 read 0.127).
// The level set at the point itself is 0: refused, with its value and what POINT needs.
TEST(InputChecks, JonctionPointOnTheParentInterfaceIsRefused) {
    const auto mesh = quad4(4, 0.5);
    for (const char* point : {"(3,0)", "(0,0)", "(1,0)"}) {
        SCOPED_TRACE(point);
        const auto r = runOn(*mesh, ssnv511aWithPoint(std::string("POINT=") + point));
        const std::string shown = std::string(point).replace(std::string(point).find(','), 1, ", ");
        expectRefused(r, "DEFI_FISS_XFEM", 43,
                      {"JONCTION[1]/POINT=" + shown +
                           ": the level set of the master interface FISS1 is 0 at that point",
                       "(interpolated in cell M", "(QUAD4) containing it): the point lies on that interface",
                       "POINT must lie strictly on one side of FISS1",
                       "|LSN| above 2.5e-06 there (1e-06 times the level set's variation across the cell)"});
    }
}

// One coordinate in 2D used to be completed with y = 0 (on FISS1 here); a boolean is no real.
TEST(InputChecks, JonctionPointNeedsTheMeshDimension) {
    const auto mesh = quad4(4, 0.5);
    auto r = runOn(*mesh, ssnv511aWithPoint("POINT=(5,)"));
    expectRefused(r, "DEFI_FISS_XFEM", 43,
                  {"JONCTION[1]/POINT=(5): 1 coordinate(s) on a mesh of dimension 2; give 2 (X, Y)"});
    r = runOn(*mesh, ssnv511aWithPoint("POINT=7"));
    expectRefused(r, "DEFI_FISS_XFEM", 43,
                  {"JONCTION[1]/POINT=(7): 1 coordinate(s) on a mesh of dimension 2; give 2 (X, Y)"});
    r = runOn(*mesh, ssnv511aWithPoint("POINT=True"));
    expectRefused(r, "DEFI_FISS_XFEM", 43, {"keyword JONCTION[1]/POINT: True is not of type real"});
    r = runOn(*mesh, ssnv511aWithPoint("POINT=(0,5,2)"));
    expectRefused(r, "DEFI_FISS_XFEM", 43,
                  {"JONCTION[1]/POINT=(0, 5, 2): 3 coordinate(s) on a mesh of dimension 2; give 2 (X, Y)"});
}

TEST(InputChecks, JonctionPointOutsideTheMeshIsRefused) {
    const auto r = runOn(*quad4(4), ssnv511aWithPoint("POINT=(0,50)"));
    expectRefused(r, "DEFI_FISS_XFEM", 43,
                  {"JONCTION[1]/POINT=(0, 50): the point lies in no cell of mesh MAILLAG (bounding box [-5, 5] x "
                   "[-5, 5]); POINT must lie inside the mesh"});
}

// The valid counterparts. Rows at y = -0.5 and 2 (N = 4, moved by -0.2 of a cell): POINT=(0, 0.2)
// is above FISS1 but nearest to the node (0, -0.5) below it, so the nearest node's side (code_aster's
// rule) gave the lower branch (NOOK); the side at the point gives ssnv511a's exact answer. A 2D
// point given as (x, y, 0) is the mesh's plane.
TEST(InputChecks, JonctionSideIsTheSideOfThePoint) {
    const auto mesh = quad4(4, -0.2);
    for (const char* point : {"POINT=(0,0.2)", "POINT=(0,5)", "POINT=(0,5,0)"}) {
        SCOPED_TRACE(point);
        const auto r = runOn(*mesh, ssnv511aWithPoint(point));
        EXPECT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("all 18 reference checks OK"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("junction on FISS1: the interface exists where -1 * LSN(FISS1) < 0"),
                  std::string::npos);
        EXPECT_TRUE(r.exists("out/t.rmed"));
    }
}

// Coordinates x 1e200 used to end in "JONCTION[1]: the mesh has no node" (every squared distance
// to POINT overflowed) or cells called degenerate (det J overflowed): LIRE_MAILLAGE names the cause.
// x 1e45 runs: every displacement check is exact, and the L2 norm of tabL2 scales by 1e45 (the
// file's reference 6.8465 is for the unit square, its only NOOK).
TEST(InputChecks, CoordinatesOutOfDoublePrecisionRangeAreRefused) {
    auto r = runOn(*quad4(4, 0.0, 1e200), ssnv511aWithPoint("POINT=(0,5e200)"));
    expectRefused(r, "LIRE_MAILLAGE", 24,
                  {"/mesh.med: node N1 has the coordinate -5e+200, beyond 1e+50: the finite elements form products "
                   "of up to three lengths",
                   "express the mesh in another length unit"});
    r = runOn(*quad4(4, 0.0, 1e-200), ssnv511aWithPoint("POINT=(0,5e-200)"));
    expectRefused(r, "LIRE_MAILLAGE", 24,
                  {"the mesh measures 1e-199 (largest side of its bounding box), below 1e-50", "underflow"});

    r = runOn(*quad4(4, 0.0, 1e45),
              ssnv511aWith({{"POINT=(0,5)", "POINT=(0,5e45)"}, {"POINT=(0,-5)", "POINT=(0,-5e45)"}}));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("1 of 18 reference checks NOOK"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("NOOK ANALYTIQUE       TEST_TABLE (t.comm line 309) tabL2 REFERENCE [GROUP_MA EQ 'TOTAL']: "
                            "computed 6.84653196881457"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("e+45, expected 6.84653196881,"), std::string::npos) << r.output;
    EXPECT_TRUE(r.exists("out/t.rmed"));
}

// NaN and Inf coordinates were read without a word (the nodes of skin cells or of no cell escape
// the Jacobian check); a .mail number beyond double precision was read as an unset value.
TEST(InputChecks, NonFiniteCoordinatesAreRefused) {
    const std::string comm = "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n";
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        auto mesh = quad4(4);
        mesh->coords[6][1] = bad;
        const auto r = runOn(*mesh, comm);
        expectRefused(r, "LIRE_MAILLAGE", 2,
                      {"/mesh.med: node N7 has a non-finite coordinate: (-2.5, " +
                       std::string(std::isnan(bad) ? "nan" : "inf") + ", 0)"});
    }
    const auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='ASTER')\nFIN()\n");
    writeText(dir / "t.export", "F comm t.comm D 1\nF mail m.mail D 20\n");
    writeText(dir / "m.mail",
              "COOR_2D\nN1 0.0 0.0\nN2 1.0E400 0.0\nN3 0.0 1.0\nFINSF\nTRIA3\nM1 N1 N2 N3\nFINSF\nFIN\n");
    auto r = runMiniaster(dir, "t.export");
    expectRefused(r, "LIRE_MAILLAGE", 2,
                  {"m.mail', line 3: the number '1.0E400' is beyond double precision (magnitude 1.8E+308 at most)"});
    writeText(dir / "m.mail",
              "COOR_2D\nN1 0.0 0.0\nN2 1.0 1.0E-400\nN3 0.0 1.0\nFINSF\nTRIA3\nM1 N1 N2 N3\nFINSF\nFIN\n");
    r = runMiniaster(dir, "t.export");
    EXPECT_EQ(r.status, 0) << "an underflow is 0:\n" << r.output;
}

// One cell replaced by a copy of its neighbour: a hole and an overlap. code_aster's VERI_MAIL
// (chckma) warns (MODELISA8_13, an alarm) and runs; so does miniaster, naming both cells.
TEST(InputChecks, DuplicatedCellIsReportedWithBothCells) {
    auto mesh = quad4(4);
    // M22 and M23 are neighbours in the second row of the 4 x 4 QUAD4 cells (after the 16 SEG2).
    const int copy = mesh->findCell("M22"), of = mesh->findCell("M23");
    ASSERT_EQ(mesh->cellTypes[size_t(copy)], ma::CellType::QUAD4);
    for (int k = 0; k < 4; ++k)
        mesh->connectivity[size_t(mesh->cellOffsets[size_t(copy)] + k)] =
            mesh->connectivity[size_t(mesh->cellOffsets[size_t(of)] + k)];
    const auto r = runOn(*mesh, "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("<A> <MODELISA8_13>"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1 pair(s) of cells have the same nodes (double cells): M22 and M23 (QUAD4); the domain is "
                            "counted twice there"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : <A>_ALARM"), std::string::npos);
    // VERIF='NON' looks for none of it, and says so (code_aster's MODELISA5_49).
    const auto off = runOn(*mesh, "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', VERI_MAIL=_F(VERIF='NON'))\nFIN()\n");
    EXPECT_EQ(off.status, 0) << off.output;
    EXPECT_EQ(off.output.find("MODELISA8_13"), std::string::npos) << off.output;
    EXPECT_NE(off.output.find("<A> <MODELISA5_49>"), std::string::npos) << off.output;

    // The same node twice in a cell stops code_aster (MODELISA4_10): an error.
    auto repeated = quad4(4);
    repeated->connectivity[size_t(repeated->cellOffsets[size_t(copy)] + 2)] =
        repeated->connectivity[size_t(repeated->cellOffsets[size_t(copy)])];
    expectRefused(runOn(*repeated, "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n"), "LIRE_MAILLAGE", 2,
                  {"1 cell(s) have the same node twice in their connectivity", "code_aster stops on them too",
                   "M22 (QUAD4): N"});
}

// VERI_MAIL/APLAT (default 1e-3): a cell whose nodes nearly coincide is code_aster's alarm
// MODELISA8_15, with the ratio of its shortest to its longest distance between two nodes.
TEST(InputChecks, FlatCellIsAnAlarm) {
    const auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='ASTER')\nFIN()\n");
    writeText(dir / "t.export", "F comm t.comm D 1\nF mail m.mail D 20\n");
    writeText(dir / "m.mail",
              "COOR_2D\nN1 0.0 0.0\nN2 1.0 0.0\nN3 1.0 1.0E-4\nN4 0.0 1.0E-4\nN5 0.0 1.0\nFINSF\n"
              "QUAD4\nM1 N1 N2 N3 N4\nFINSF\nTRIA3\nM2 N4 N3 N5\nFINSF\nFIN\n");
    const auto r = runMiniaster(dir, "t.export");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("1 cell(s) have nearly coincident nodes, their shortest distance between two nodes below "
                            "APLAT = 0.001 times their longest: M1 (QUAD4) ratio 0.0001"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("<A> <MODELISA8_15>"), std::string::npos) << r.output;
}

// A group the mesh does not have is an error wherever a command names one (code_aster:
// "le GROUP_MA ... ne fait pas partie du maillage"), COMPORTEMENT included, with the command, the
// keyword, the name and the line.
TEST(InputChecks, UnknownGroupsAreRefusedEverywhere) {
    const std::string comm = R"(DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA=@DG@))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=@AM@, PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=1e8, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(GROUP_MA=@MAT@, MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA=@DDL@, DX=0.0), _F(GROUP_NO=@DDLNO@, DY=0.0)),
                    PRES_REP=_F(GROUP_MA=@PRES@, PRES=1e6), FORCE_INTERNE=_F(GROUP_MA=@FI@, FX=0.0))
LI = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=1))
RES = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH), INCREMENT=_F(LIST_INST=LI),
                    COMPORTEMENT=_F(GROUP_MA=@COMP@, RELATION='ELAS'))
U = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=RES, NOM_CHAM='DEPL', INST=1.0)
def zero(x): return 0.0
ER = POST_ERREUR(OPTION='DEPL_RELA', MODELE=MO, GROUP_MA=@PE@, CHAM_GD=U,
                 DX=FORMULE(VALE='zero(X)', zero=zero, NOM_PARA=['X', 'Y']))
D = POST_RELEVE_T(ACTION=_F(INTITULE='DEPL', GROUP_NO=@PR@, RESULTAT=RES, NOM_CHAM='DEPL', NUME_ORDRE=1,
                            TOUT_CMP='OUI', OPERATION='EXTRACTION'))
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU_2D=_F(GROUP_MA=@OP@, GROUP_MA_SURF=@OPS@))
IMPR_RESU(FORMAT='GMSH', UNITE=37, RESU=_F(RESULTAT=RES, NOM_CHAM='DEPL', GROUP_MA=@GM@))
FIN()
)";
    const std::vector<std::tuple<std::string, std::string, std::string, int, std::string>> places{
        // placeholder, valid group, command, line, keyword and kind in the message
        {"DG", "'LD'", "DEFI_GROUP", 3, "CREA_GROUP_NO[1]/GROUP_MA: the mesh MA has no cell"},
        {"AM", "('SURF', 'LD')", "AFFE_MODELE", 4, "AFFE[1]/GROUP_MA: the mesh MA has no cell"},
        {"MAT", "'SURF'", "AFFE_MATERIAU", 6, "AFFE[1]/GROUP_MA: the mesh MA has no cell"},
        {"DDL", "'LG'", "AFFE_CHAR_MECA", 7, "DDL_IMPO[1]/GROUP_MA: the mesh MA has no cell"},
        {"DDLNO", "'LD'", "AFFE_CHAR_MECA", 7, "DDL_IMPO[2]/GROUP_NO: the mesh MA has no node"},
        {"PRES", "'LD'", "AFFE_CHAR_MECA", 7, "PRES_REP[1]/GROUP_MA: the mesh MA has no cell"},
        {"FI", "'SURF'", "AFFE_CHAR_MECA", 7, "FORCE_INTERNE[1]/GROUP_MA: the mesh MA has no cell"},
        {"COMP", "'SURF'", "STAT_NON_LINE", 10, "COMPORTEMENT[1]/GROUP_MA: the mesh MA has no cell"},
        {"PE", "'SURF'", "POST_ERREUR", 14, "GROUP_MA: the mesh MA has no cell"},
        {"PR", "'LD'", "POST_RELEVE_T", 16, "ACTION[1]/GROUP_NO: the mesh MA has no node"},
        {"OP", "'LD'", "MODI_MAILLAGE", 18, "ORIE_PEAU_2D[1]/GROUP_MA: the mesh MA has no cell"},
        {"OPS", "'SURF'", "MODI_MAILLAGE", 18, "ORIE_PEAU_2D[1]/GROUP_MA_SURF: the mesh MA has no cell"},
        {"GM", "'SURF'", "IMPR_RESU", 19, "RESU[1]/GROUP_MA: the mesh MA has no cell"},
    };
    auto withGroups = [&](const std::string& unknown) {
        std::string text = comm;
        for (const auto& [key, valid, command, line, message] : places) {
            const std::string mark = "@" + key + "@";
            text.replace(text.find(mark), mark.size(), key == unknown ? "'XYZ'" : valid);
        }
        return text;
    };
    const auto mesh = quad4(4);
    const auto valid = runOn(*mesh, withGroups(""));
    ASSERT_EQ(valid.status, 0) << valid.output;
    for (const auto& [key, group, command, line, message] : places) {
        SCOPED_TRACE(key);
        expectRefused(runOn(*mesh, withGroups(key)), command, line, {message + " group 'XYZ'"});
    }
}
