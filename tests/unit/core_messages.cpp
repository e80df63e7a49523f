// The message tables (core/Message.hpp): each text formats to the exact words of the .mess, and an
// alarm box frames it in code_aster's style.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "contact/ContactMessages.hpp"
#include "core/Messages.hpp"
#include "fe/FeMessages.hpp"
#include "fe/Material.hpp"
#include "med_io/MedMessages.hpp"
#include "mesh/MeshMessages.hpp"
#include "parser/ParserMessages.hpp"
#include "post/PostMessages.hpp"
#include "solver/SolverMessages.hpp"
#include "xfem/XfemMessages.hpp"

namespace {

using namespace ma;

// Escaped braces are text; the count is what the consteval constructor compares with the arguments.
static_assert(detail::replacementFields("{} and {:.3e}, {{literal}}") == 2);
static_assert(detail::replacementFields("no field") == 0);

TEST(Messages, FormatTheirArgumentsWithTheirSpecs) {
    EXPECT_EQ(format(XFEM_63, 7),
              "7 nodal level-set values were moved onto the interface (their zero lay within 1e-6 of an edge end)");
    EXPECT_EQ(format(FACTOR_57, 1.5e-3),
              "The relative residual of the linear solve is 1.500e-03: the solution is inaccurate (ill-conditioned or "
              "nearly singular system).");
    EXPECT_EQ(format(CONTACT_SLIVER, 3, "total area", 2.5e-4, 1e-9).substr(0, 110),
              "3 sub-cell face(s) on the contact interfaces (total area 2.500e-04, 1.0e-09 of the interfaces) have no "
              "sub-cel");
    EXPECT_EQ(format(MAILLAGE_ORIENTATION, "MAILLAG", 25, "left-handed", "25 of 25 HEXA8"),
              "mesh MAILLAG: 25 cells are left-handed in code_aster's node order (negative Jacobian): 25 of 25 HEXA8; "
              "they are integrated with |det J|, as code_aster does, and give the same elements as cells numbered "
              "the other way");
    EXPECT_EQ(format(XFEM_SUBCELL_RULE, 1, "HEXA8", 2, "FPG1", 21, "HEXA8", 2),
              "--subcell-quadrature 1: the strains of the HEXA8 shape functions are polynomials of degree 2 on the "
              "sub-cells, which the rule FPG1 does not integrate exactly: uniform stress states are no longer "
              "reproduced on the 21 X-FEM HEXA8 elements (the patch test fails, the answer carries a quadrature "
              "error). Use a degree >= 2.");
    EXPECT_EQ(format(MED_ELGA, "RESU_SIEF_ELGA", 4, "PENTA15 PYRAM5"),
              "field RESU_SIEF_ELGA: 4 elements of types PENTA15 PYRAM5 have no reference element in miniaster; their "
              "values are not printed");
    EXPECT_EQ(format(SUPERVIS_4, "SyntaxError: x"),
              "the check of the command file before its run failed (a defect of miniaster; the file runs unchecked): "
              "SyntaxError: x");
}

TEST(Messages, FormattedKeepsTheId) {
    const FormattedMessage m = formatted(MODELISA4_80, "t.mail", 23, "GROUP_NO", "NOTHING");
    EXPECT_EQ(m.id, "MODELISA4_80");
    EXPECT_EQ(m.text, "mesh t.mail, line 23: GROUP_NO 'NOTHING' is empty and is not created");
    const FormattedMessage n = formatted(MECANONLINE5_37, 0.5, 10, 2.5e-3, 1.25);
    EXPECT_EQ(n.id, "MECANONLINE5_37");
    EXPECT_EQ(n.text,
              "Newton did not converge at INST 0.5 in 10 iterations (ITER_GLOB_MAXI): RESI_GLOB_RELA = 2.500e-03, "
              "RESI_GLOB_MAXI = 1.250e+00\nARRET='NON': the computation goes on with this unconverged state.");
}

TEST(Messages, OneIdTwoTexts) {
    Material m;
    m.E = 1.0;
    m.nu = 0.4999999;
    const auto near = nearlyDegenerateElasticity(m, "DEFI_MATERIAU/ELAS/NU");
    ASSERT_TRUE(near.has_value());
    EXPECT_EQ(near->id, "MATERIAL_1");
    EXPECT_EQ(near->text,
              "DEFI_MATERIAU/ELAS/NU: NU = 0.4999999 is nearly incompressible in 3D and plane strain (1 - 2 NU = "
              "2.0e-07, lambda/mu = 5.0e+06): the stiffness matrix is singular to working precision (displacement "
              "elements lock); use NU <= 0.4999");
    m.nu = -0.9999999;
    EXPECT_EQ(nearlyDegenerateElasticity(m, "material M")->text,
              "material M: NU = -0.9999999 is close to -1 (1 + NU = 1.0e-07): the shear modulus E/(2(1+NU)) is "
              "nearly infinite and the stiffness matrix singular to working precision");
    m.nu = 0.3;
    EXPECT_FALSE(nearlyDegenerateElasticity(m, "material M").has_value());
    EXPECT_STREQ(XFEM_DDL_INACTIVE_SLOT.id, XFEM_DDL_INTERFACE_NODES.id);
}

TEST(Messages, AlarmBoxFramesEveryLine) {
    msg().setEcho(false);
    msg().reset();
    msg().alarm(TEST0_11);
    msg().alarm(SOUSTRUC_37, "G1");
    const std::string bar = "   !" + std::string(70, '-') + "!\n";
    const std::string tail =
        "   ! Ceci est une alarme. Si vous ne comprenez pas le sens de cette\n"
        "   ! alarme, vous pouvez obtenir des resultats inattendus !\n";
    EXPECT_EQ(msg().messText(),
              bar +
                  "   ! <A> <TEST0_11>\n"
                  "   ! A non-regression test with a null VALE_CALC is meaningless: the check is skipped.\n"
                  "   ! Give ORDRE_GRANDEUR (with CRITERE='ABSOLU') or a reference value.\n" +
                  tail + bar + bar +
                  "   ! <A> <SOUSTRUC_37>\n   ! node group 'G1' already exists: it is kept as it is\n" + tail + bar);
    EXPECT_EQ(msg().alarmCount(), 2);
    msg().reset();
}

}  // namespace
