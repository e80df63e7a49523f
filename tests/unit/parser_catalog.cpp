// The catalog and the validation layer: normalisation of values, defaults, blocks, rules, legacy
// syntaxes, consistency of every entry (a command file using every catalogued command, checked
// by the binary: tests/cli/parser_syntax_check.cpp).
#include <gtest/gtest.h>

#include <set>

#include "core/Error.hpp"
#include "parser/Catalog.hpp"

using namespace ma;

namespace {

class FakeConcept : public Concept {
public:
    explicit FakeConcept(std::string type, std::string n = "OBJ") : type_(std::move(type)) { name = std::move(n); }
    std::string typeName() const override { return type_; }

private:
    std::string type_;
};

ConceptPtr fake(const std::string& type, const std::string& name = "OBJ") {
    return std::make_shared<FakeConcept>(type, name);
}

KeywordSet validate(const std::string& command, const CallArguments& args) {
    const auto* c = Catalog::instance().find(command);
    if (!c) throw std::logic_error("no catalog entry " + command);
    return validateCall(*c, args);
}

using V = CallValue;

}  // namespace

TEST(ParserCatalog, ScalarBecomesAListAndOneTupleIsUnwrapped) {
    // GROUP_MA (max > 1) given as a scalar, TOUT (max 1) given as a 1-tuple, MATER max 30.
    auto kw =
        validate("AFFE_MATERIAU",
                 {{"MAILLAGE", V::of(fake("maillage_sdaster"))},
                  {"AFFE",
                   V::list({V::factor({{"TOUT", V::list({V::of("OUI")})}, {"MATER", V::of(fake("mater_sdaster"))}}),
                            V::factor({{"GROUP_MA", V::of("SURF")}, {"MATER", V::of(fake("mater_sdaster"))}})})}});
    ASSERT_EQ(kw.factor("AFFE").size(), 2u);
    EXPECT_EQ(kw.factor("AFFE")[0].text("TOUT"), "OUI");
    EXPECT_EQ(kw.factor("AFFE")[1].texts("GROUP_MA"), std::vector<std::string>{"SURF"});
    EXPECT_EQ(kw.factor("AFFE")[1].path(), "AFFE[2]");
}

TEST(ParserCatalog, TwoValuesForASingleValueKeywordIsAnError) {
    try {
        validate("DEFI_FONCTION",
                 {{"NOM_PARA", V::list({V::of("INST"), V::of("X")})}, {"VALE", V::list({V::of(0.0), V::of(1.0)})}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "keyword NOM_PARA accepts at most 1 value, got 2: ('INST', 'X')");
    }
}

TEST(ParserCatalog, IntegersAreAcceptedForRealsAndDefaultsAreFilled) {
    auto kw = validate("DEFI_FONCTION", {{"NOM_PARA", V::of("INST")},
                                         {"VALE", V::list({V::of(0LL), V::of(0LL), V::of(1LL), V::of(2.5)})}});
    const auto& vale = kw.values("VALE");
    ASSERT_EQ(vale.size(), 4u);
    for (const auto& v : vale) EXPECT_TRUE(std::holds_alternative<double>(v));
    EXPECT_EQ(kw.reals("VALE"), (std::vector<double>{0.0, 0.0, 1.0, 2.5}));
    EXPECT_EQ(kw.text("PROL_GAUCHE"), "EXCLU");
    EXPECT_EQ(kw.text("PROL_DROITE"), "EXCLU");
    EXPECT_EQ(kw.text("INTERPOL"), "LIN");
    EXPECT_EQ(kw.text("VERIF"), "CROISSANT");
    EXPECT_EQ(kw.integer("INFO"), 1);
}

TEST(ParserCatalog, DefaultOccurrenceOfAFactorKeyword) {
    // STAT_NON_LINE without NEWTON / CONVERGENCE / SOLVEUR gets code_aster's defaults.
    auto kw = validate("STAT_NON_LINE", {{"MODELE", V::of(fake("modele_sdaster"))},
                                         {"CHAM_MATER", V::of(fake("cham_mater"))},
                                         {"EXCIT", V::factor({{"CHARGE", V::of(fake("char_meca"))}})},
                                         {"INCREMENT", V::factor({{"LIST_INST", V::of(fake("listr8_sdaster"))}})}});
    ASSERT_EQ(kw.factor("NEWTON").size(), 1u);
    EXPECT_EQ(kw.factor("NEWTON")[0].integer("REAC_INCR"), 1);
    EXPECT_EQ(kw.factor("NEWTON")[0].text("MATRICE"), "TANGENTE");
    EXPECT_EQ(kw.factor("CONVERGENCE")[0].integer("ITER_GLOB_MAXI"), 10);
    EXPECT_EQ(kw.factor("CONVERGENCE")[0].text("ARRET"), "OUI");
    // RESI_GLOB_RELA = 1e-6 when no criterion is given, none when RESI_GLOB_MAXI alone is.
    EXPECT_EQ(kw.factor("CONVERGENCE")[0].real("RESI_GLOB_RELA"), 1e-6);
    auto maxi = validate("STAT_NON_LINE", {{"MODELE", V::of(fake("modele_sdaster"))},
                                           {"CHAM_MATER", V::of(fake("cham_mater"))},
                                           {"EXCIT", V::factor({{"CHARGE", V::of(fake("char_meca"))}})},
                                           {"INCREMENT", V::factor({{"LIST_INST", V::of(fake("listr8_sdaster"))}})},
                                           {"CONVERGENCE", V::factor({{"RESI_GLOB_MAXI", V::of(1e-6)}})}});
    EXPECT_FALSE(maxi.factor("CONVERGENCE")[0].has("RESI_GLOB_RELA"));
    EXPECT_EQ(kw.factor("SOLVEUR")[0].text("METHODE"), "MUMPS");
    EXPECT_EQ(kw.factor("SOLVEUR")[0].integer("NPREC"), 8);
    EXPECT_EQ(kw.factor("EXCIT")[0].text("TYPE_CHARGE"), "FIXE_CSTE");
    EXPECT_FALSE(kw.has("COMPORTEMENT"));
}

TEST(ParserCatalog, BlocksFollowTheValueOfTheirKeyword) {
    auto table = V::of(fake("table_sdaster", "DEP"));
    // FILTRE with the default CRIT_COMP='EQ': CRITERE / PRECISION defaults; REGEXP: VALE_K only.
    auto kw = validate(
        "CALC_TABLE",
        {{"TABLE", table},
         {"ACTION",
          V::list({V::factor({{"OPERATION", V::of("FILTRE")}, {"NOM_PARA", V::of("COOR_X")}, {"VALE", V::of(0.02)}}),
                   V::factor({{"OPERATION", V::of("FILTRE")},
                              {"NOM_PARA", V::of("NOEUD")},
                              {"CRIT_COMP", V::of("REGEXP")},
                              {"VALE_K", V::of("NP")}})})}});
    const auto& a = kw.factor("ACTION");
    EXPECT_EQ(a[0].text("CRIT_COMP"), "EQ");
    EXPECT_EQ(a[0].text("CRITERE"), "RELATIF");
    EXPECT_DOUBLE_EQ(a[0].real("PRECISION"), 1e-3);
    EXPECT_FALSE(a[1].has("CRITERE"));
    EXPECT_EQ(a[1].text("VALE_K"), "NP");
    // A keyword of another block is refused with the condition that would allow it.
    try {
        validate("CALC_TABLE", {{"TABLE", table},
                                {"ACTION", V::factor({{"OPERATION", V::of("EXTR")},
                                                      {"NOM_PARA", V::of("DX")},
                                                      {"FORMULE", V::of(fake("formule"))}})}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(),
                     "keyword ACTION[1]/FORMULE is not allowed here: it is only accepted when OPERATION='OPER'");
    }
}

TEST(ParserCatalog, TestTableReferenceBlockAndLegacyVale) {
    auto table = V::of(fake("table_sdaster", "T"));
    auto kw = validate("TEST_TABLE", {{"TABLE", table},
                                      {"NOM_PARA", V::of("DX")},
                                      {"VALE_CALC", V::of(1LL)},
                                      {"VALE_REFE", V::of(1LL)},
                                      {"REFERENCE", V::of("ANALYTIQUE")}});
    EXPECT_DOUBLE_EQ(kw.real("PRECISION"), 1e-3);
    EXPECT_DOUBLE_EQ(kw.real("TOLE_MACHINE"), 1e-6);
    EXPECT_EQ(kw.text("CRITERE"), "RELATIF");
    // No REFERENCE: no PRECISION (reference mode off, commands_spec §1.2).
    auto nr = validate("TEST_TABLE", {{"TABLE", table}, {"NOM_PARA", V::of("DX")}, {"VALE_CALC", V::of(1.0)}});
    EXPECT_FALSE(nr.has("PRECISION"));
    // Legacy VALE= with PRECISION and no REFERENCE (files up to 2012).
    auto legacy =
        validate("TEST_TABLE",
                 {{"TABLE", table}, {"NOM_PARA", V::of("DX")}, {"VALE", V::of(0LL)}, {"PRECISION", V::of(1e-4)}});
    EXPECT_DOUBLE_EQ(legacy.real("PRECISION"), 1e-4);
    EXPECT_DOUBLE_EQ(legacy.reals("VALE")[0], 0.0);
    try {
        validate("TEST_TABLE", {{"TABLE", table}, {"NOM_PARA", V::of("DX")}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(),
                     "exactly one of VALE_CALC, VALE_CALC_I, VALE_CALC_K, VALE, VALE_I must be given (rule "
                     "UN_PARMI), got none");
    }
}

TEST(ParserCatalog, LegacySyntaxesAreMappedToTheCurrentOnes) {
    // MODI_MODELE_XFEM CONTACT='OUI' / 'P1P1' (2011-2014) -> 'STANDARD'.
    for (const char* old : {"OUI", "P1P1"}) {
        auto kw = validate("MODI_MODELE_XFEM", {{"MODELE_IN", V::of(fake("modele_sdaster"))},
                                                {"FISSURE", V::of(fake("fiss_xfem"))},
                                                {"CONTACT", V::of(old)}});
        EXPECT_EQ(kw.text("CONTACT"), "STANDARD");
        EXPECT_EQ(kw.objects<Concept>("FISSURE").size(), 1u);
    }
    // COMP_ELAS (≤ 2013) is read as COMPORTEMENT; both together are refused.
    CallArguments snl{{"MODELE", V::of(fake("modele_sdaster"))},
                      {"CHAM_MATER", V::of(fake("cham_mater"))},
                      {"EXCIT", V::factor({{"CHARGE", V::of(fake("char_meca"))},
                                           {"FONC_MULT", V::of(fake("fonction_sdaster"))}})},
                      {"COMP_ELAS", V::factor({{"RELATION", V::of("ELAS")}})},
                      {"INCREMENT", V::factor({{"LIST_INST", V::of(fake("listr8_sdaster"))}})},
                      {"CONVERGENCE", V::factor({{"ARRET", V::of("NON")}, {"ITER_GLOB_MAXI", V::of(20LL)}})},
                      {"SOLVEUR", V::factor({{"METHODE", V::of("MUMPS")}, {"PCENT_PIVOT", V::of(250LL)}})}};
    auto kw = validate("STAT_NON_LINE", snl);
    ASSERT_EQ(kw.factor("COMPORTEMENT").size(), 1u);
    EXPECT_FALSE(kw.has("COMP_ELAS"));
    EXPECT_EQ(kw.factor("COMPORTEMENT")[0].text("DEFORMATION"), "PETIT");
    EXPECT_EQ(kw.factor("SOLVEUR")[0].integer("PCENT_PIVOT"), 250);
    snl.emplace_back("COMPORTEMENT", V::factor({{"RELATION", V::of("ELAS")}}));
    try {
        validate("STAT_NON_LINE", snl);
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "COMP_ELAS (older name of COMPORTEMENT) cannot be given together with COMPORTEMENT");
    }
}

TEST(ParserCatalog, UnsupportedIsDistinctFromUnknown) {
    auto model = V::of(fake("modele_sdaster"));
    auto crack = V::of(fake("fiss_xfem"));
    try {
        validate("DEFI_CONTACT", {{"MODELE", model},
                                  {"FORMULATION", V::of("XFEM")},
                                  {"ZONE", V::factor({{"FISS_MAIT", crack}, {"COEF_FROT", V::of(0.3)}})}});
        FAIL();
    } catch (const NotImplemented& e) {
        EXPECT_STREQ(e.what(),
                     "keyword ZONE[1]/COEF_FROT is not supported by miniaster (friction is not modelled "
                     "(frictionless contact only))");
    }
    try {
        validate("DEFI_CONTACT", {{"MODELE", model},
                                  {"FORMULATION", V::of("XFEM")},
                                  {"ZONE", V::factor({{"FISS_MAIT", crack}, {"COEF_FROTT", V::of(0.3)}})}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown keyword ZONE[1]/COEF_FROTT for DEFI_CONTACT"), std::string::npos);
    }
    try {
        validate("DEFI_CONTACT",
                 {{"MODELE", model}, {"FORMULATION", V::of("CONTINUE")}, {"ZONE", V::factor({{"FISS_MAIT", crack}})}});
        FAIL();
    } catch (const NotImplemented& e) {
        EXPECT_STREQ(e.what(), "keyword FORMULATION: value 'CONTINUE' is not supported by miniaster");
    }
}

TEST(ParserCatalog, ContextKeywordsOfFormule) {
    CallArguments context;
    const auto* c = Catalog::instance().find("FORMULE");
    auto kw =
        validateCall(*c, {{"VALE", V::of("depx(X, Y)")}, {"depx", V::of(1LL)}, {"NOM_PARA", V::of("X")}}, &context);
    EXPECT_EQ(kw.texts("NOM_PARA"), std::vector<std::string>{"X"});
    ASSERT_EQ(context.size(), 1u);
    EXPECT_EQ(context[0].first, "depx");
}

// Every entry is consistent: rules name keywords of their level, defaults satisfy `into`,
// names are unique per level (outside blocks), reentrant commands are the documented ones.
namespace {
void checkLevel(const std::string& where, const std::vector<cata::Keyword>& content,
                const std::vector<cata::Rule>& rules, std::set<std::string> names) {
    std::set<std::string> unconditional;
    for (const auto& k : content) {
        if (k.kind == cata::Keyword::Kind::Block) continue;
        EXPECT_TRUE(unconditional.insert(k.name).second) << where << ": duplicate keyword " << k.name;
    }
    for (const auto& k : content) {
        if (k.kind == cata::Keyword::Kind::Block) {
            std::set<std::string> inner = names;
            for (const auto& b : k.content) inner.insert(b.name);
            for (const auto& b : k.content) names.insert(b.name);
            checkLevel(where + "{" + k.condition.describe() + "}", k.content, k.rulesList, inner);
            continue;
        }
        names.insert(k.name);
        if (k.kind == cata::Keyword::Kind::Factor) checkLevel(where + "/" + k.name, k.content, k.rulesList, {});
        for (const auto& d : k.defaultValues) {
            if (std::holds_alternative<std::string>(d) && !k.intoTexts.empty()) {
                EXPECT_NE(std::find(k.intoTexts.begin(), k.intoTexts.end(), std::get<std::string>(d)),
                          k.intoTexts.end())
                    << where << "/" << k.name << ": default not in the allowed values";
            }
            if (std::holds_alternative<long long>(d) && !k.intoInts.empty()) {
                EXPECT_NE(std::find(k.intoInts.begin(), k.intoInts.end(), std::get<long long>(d)), k.intoInts.end())
                    << where << "/" << k.name;
            }
        }
    }
    for (const auto& k : content)
        if (k.kind != cata::Keyword::Kind::Block) names.insert(k.name);
    for (const auto& r : rules)
        for (const auto& n : r.keywords) EXPECT_TRUE(names.count(n)) << where << ": rule names unknown keyword " << n;
}
}  // namespace

TEST(ParserCatalog, EveryEntryIsConsistent) {
    std::set<std::string> reentrant;
    for (const auto& [name, c] : Catalog::instance().commands()) {
        EXPECT_EQ(name, c.name);
        std::set<std::string> top;
        for (const auto& k : c.content)
            if (k.kind == cata::Keyword::Kind::Block)
                for (const auto& b : k.content) top.insert(b.name);
        checkLevel(name, c.content, c.rulesList, top);
        if (c.reentrant != cata::Reuse::No) reentrant.insert(name);
    }
    EXPECT_EQ(reentrant, (std::set<std::string>{"CALC_CHAMP", "CALC_TABLE", "DEFI_GROUP", "MECA_STATIQUE",
                                                "MODI_MAILLAGE", "STAT_NON_LINE"}));
    EXPECT_GE(Catalog::instance().commands().size(), 28u);
}
