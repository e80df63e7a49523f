// Test accounting: the TEST lines recorded by TEST_TABLE drive the summary, the diagnostic and the
// exit status. The supervisor runs in-process with a stand-in TEST_TABLE that records what the
// command file asks (so that this test does not depend on the table engine).
#include <gtest/gtest.h>

#include "core/Messages.hpp"
#include "core/TestReport.hpp"
#include "parser/CommandRegistry.hpp"
#include "parser/Supervisor.hpp"
#include "parser_run.hpp"

TEST(ParserTestReport, SummaryCountsPerCategory) {
    ma::TestReport report;
    using S = ma::TestLine::Status;
    report.add({"NON_REGRESSION", S::Ok, "a"});
    report.add({"ANALYTIQUE", S::Ok, "b"});
    report.add({"NON_REGRESSION", S::Skip, "c"});
    report.add({"ANALYTIQUE", S::Nook, "TEST_TABLE DEPZON_1 DX MIN: computed -0.24, expected -0.25"});
    EXPECT_EQ(report.count(S::Ok, true), 1);
    EXPECT_EQ(report.count(S::Ok, false), 1);
    EXPECT_EQ(report.count(S::Skip, true), 1);
    EXPECT_EQ(report.nookCount(), 1);
    const auto s = report.summary();
    EXPECT_NE(s.find("  reference checks                 1        1      0\n"), std::string::npos) << s;
    EXPECT_NE(s.find("  non-regression checks            1        0      1\n"), std::string::npos) << s;
    EXPECT_NE(s.find("  1 of 2 reference checks NOOK\n"), std::string::npos) << s;
    EXPECT_NE(s.find("    NOOK ANALYTIQUE       TEST_TABLE DEPZON_1 DX MIN: computed -0.24, expected -0.25\n"),
              std::string::npos)
        << s;
}

TEST(ParserTestReport, SummarySaysWhenOnlyCodeAstersOwnValuesDiffer) {
    // ssnv511e-h: every reference check OK, NON_REGRESSION lines carrying code_aster's inexact values.
    ma::TestReport report;
    using S = ma::TestLine::Status;
    for (int i = 0; i < 18; ++i) report.add({"ANALYTIQUE", S::Ok, "r"});
    report.add({"NON_REGRESSION", S::Ok, "a"});
    for (int i = 0; i < 3; ++i) report.add({"NON_REGRESSION", S::Nook, "b"});
    EXPECT_NE(report.summary().find("  all 18 reference checks OK; 3 non-regression values differ from code_aster's "
                                    "own\n"),
              std::string::npos)
        << report.summary();
}

namespace {
class StandIn : public ma::Concept {
public:
    explicit StandIn(std::string type) : type_(std::move(type)) {}
    std::string typeName() const override { return type_; }

private:
    std::string type_;
};
ma::CommandFunction standIn(const std::string& type) {
    return [type](const ma::KeywordSet&, ma::CommandContext&) {
        auto c = std::make_shared<StandIn>(type);
        c->name = "NAME_IN_FILE";  // e.g. a MED mesh name: replaced by the variable's name
        return c;
    };
}
}  // namespace

TEST(ParserTestReport, NookGivesExitStatus2) {
    // Stand-ins for the engine (this test is about the supervisor): a table from POST_RELEVE_T,
    // and a TEST_TABLE that records one line per call, NOOK when LEGENDE='NOOK'.
    auto& registry = ma::CommandRegistry::instance();
    registry.add("LIRE_MAILLAGE", standIn("maillage_sdaster"));
    registry.add("AFFE_MODELE", standIn("modele_sdaster"));
    registry.add("MECA_STATIQUE", standIn("evol_elas"));
    registry.add("POST_RELEVE_T", standIn("table_sdaster"));
    registry.add("TEST_TABLE", [](const ma::KeywordSet& kw, ma::CommandContext&) {
        const auto legend = kw.text("LEGENDE");
        const auto status = legend == "NOOK" ? ma::TestLine::Status::Nook : ma::TestLine::Status::Ok;
        ma::testReport().add({"NON_REGRESSION", status, "check " + legend});
        ma::msg().result((status == ma::TestLine::Status::Nook ? "NOOK " : " OK  ") + legend);
        return ma::ConceptPtr();
    });
    auto dir = ma::test::freshDir();
    ma::test::writeText(dir / "t.comm", R"(
DEBUT()
M = LIRE_MAILLAGE()
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
R = MECA_STATIQUE(MODELE=MO)
T = POST_RELEVE_T(ACTION=_F(INTITULE='D', RESULTAT=R, NOM_CHAM='DEPL', GROUP_NO='G', TOUT_CMP='OUI',
                            OPERATION='EXTRACTION'))
for legend in ('first', 'NOOK', 'last'):
    TEST_TABLE(TABLE=T, NOM_PARA='DX', VALE_CALC=1.0, LEGENDE=legend)
FIN()
)");
    const std::string comm = (dir / "t.comm").string(), out = (dir / "out").string();
    std::vector<std::string> args{"miniaster", "run", comm, "--out-dir", out};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    ma::msg().setEcho(false);
    const int status = ma::supervisorMain(int(argv.size()), argv.data());
    EXPECT_EQ(status, 2);
    const auto mess = ma::test::RunResult{0, "", dir}.file("out/t.mess");
    EXPECT_NE(mess.find("  non-regression checks            2        1      0\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find("    NOOK NON_REGRESSION   check NOOK\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : NOOK_TEST_RESU\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find("    MAILLAGE=M,\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find("    TABLE=T,\n"), std::string::npos) << mess;
    const auto resu = ma::test::RunResult{0, "", dir}.file("out/t.resu");
    EXPECT_EQ(resu, " OK  first\nNOOK NOOK\n OK  last\n");
}
