// The catalog and the validation layer: normalisation of values, defaults, blocks, rules, legacy
// syntaxes, consistency of every entry, and a command file using every catalogued command.
#include <gtest/gtest.h>

#include <set>

#include "core/Error.hpp"
#include "parser/Catalog.hpp"
#include "parser_run.hpp"

using namespace ma;
using ma::test::runComm;

namespace {

class FakeConcept : public Concept {
public:
    explicit FakeConcept(std::string type, std::string n = "OBJ") : type_(std::move(type)) { name = std::move(n); }
    std::string typeName() const override { return type_; }

private:
    std::string type_;
};

ConceptPtr fake(const std::string& type, const std::string& name = "OBJ") { return std::make_shared<FakeConcept>(type, name); }

KeywordSet validate(const std::string& command, const CallArguments& args) {
    const auto* c = Catalog::instance().find(command);
    if (!c) throw std::logic_error("no catalog entry " + command);
    return validateCall(*c, args);
}

using V = CallValue;

}  // namespace

TEST(ParserCatalog, ScalarBecomesAListAndOneTupleIsUnwrapped) {
    // GROUP_MA (max > 1) given as a scalar, TOUT (max 1) given as a 1-tuple, MATER max 30.
    auto kw = validate("AFFE_MATERIAU",
                       {{"MAILLAGE", V::of(fake("maillage_sdaster"))},
                        {"AFFE", V::list({V::factor({{"TOUT", V::list({V::of("OUI")})},
                                                     {"MATER", V::of(fake("mater_sdaster"))}}),
                                          V::factor({{"GROUP_MA", V::of("SURF")},
                                                     {"MATER", V::of(fake("mater_sdaster"))}})})}});
    ASSERT_EQ(kw.factor("AFFE").size(), 2u);
    EXPECT_EQ(kw.factor("AFFE")[0].text("TOUT"), "OUI");
    EXPECT_EQ(kw.factor("AFFE")[1].texts("GROUP_MA"), std::vector<std::string>{"SURF"});
    EXPECT_EQ(kw.factor("AFFE")[1].path(), "AFFE[2]");
}

TEST(ParserCatalog, TwoValuesForASingleValueKeywordIsAnError) {
    try {
        validate("DEFI_FONCTION", {{"NOM_PARA", V::list({V::of("INST"), V::of("X")})}, {"VALE", V::list({V::of(0.0), V::of(1.0)})}});
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
    EXPECT_FALSE(kw.factor("CONVERGENCE")[0].has("RESI_GLOB_RELA"));  // the command applies 1e-6 when no criterion
    EXPECT_EQ(kw.factor("SOLVEUR")[0].text("METHODE"), "MUMPS");
    EXPECT_EQ(kw.factor("SOLVEUR")[0].integer("NPREC"), 8);
    EXPECT_EQ(kw.factor("EXCIT")[0].text("TYPE_CHARGE"), "FIXE_CSTE");
    EXPECT_FALSE(kw.has("COMPORTEMENT"));
}

TEST(ParserCatalog, BlocksFollowTheValueOfTheirKeyword) {
    auto table = V::of(fake("table_sdaster", "DEP"));
    // FILTRE with the default CRIT_COMP='EQ': CRITERE / PRECISION defaults; REGEXP: VALE_K only.
    auto kw = validate("CALC_TABLE", {{"TABLE", table},
                                      {"ACTION", V::list({V::factor({{"OPERATION", V::of("FILTRE")},
                                                                     {"NOM_PARA", V::of("COOR_X")},
                                                                     {"VALE", V::of(0.02)}}),
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
                                {"ACTION", V::factor({{"OPERATION", V::of("EXTR")}, {"NOM_PARA", V::of("DX")},
                                                      {"FORMULE", V::of(fake("formule"))}})}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "keyword ACTION[1]/FORMULE is not allowed here: it is only accepted when OPERATION='OPER'");
    }
}

TEST(ParserCatalog, TestTableReferenceBlockAndLegacyVale) {
    auto table = V::of(fake("table_sdaster", "T"));
    auto kw = validate("TEST_TABLE", {{"TABLE", table}, {"NOM_PARA", V::of("DX")}, {"VALE_CALC", V::of(1LL)},
                                      {"VALE_REFE", V::of(1LL)}, {"REFERENCE", V::of("ANALYTIQUE")}});
    EXPECT_DOUBLE_EQ(kw.real("PRECISION"), 1e-3);
    EXPECT_DOUBLE_EQ(kw.real("TOLE_MACHINE"), 1e-6);
    EXPECT_EQ(kw.text("CRITERE"), "RELATIF");
    // No REFERENCE: no PRECISION (reference mode off, commands_spec §1.2).
    auto nr = validate("TEST_TABLE", {{"TABLE", table}, {"NOM_PARA", V::of("DX")}, {"VALE_CALC", V::of(1.0)}});
    EXPECT_FALSE(nr.has("PRECISION"));
    // Legacy VALE= with PRECISION and no REFERENCE (files up to 2012).
    auto legacy = validate("TEST_TABLE", {{"TABLE", table}, {"NOM_PARA", V::of("DX")}, {"VALE", V::of(0LL)},
                                          {"PRECISION", V::of(1e-4)}});
    EXPECT_DOUBLE_EQ(legacy.real("PRECISION"), 1e-4);
    EXPECT_DOUBLE_EQ(legacy.reals("VALE")[0], 0.0);
    try {
        validate("TEST_TABLE", {{"TABLE", table}, {"NOM_PARA", V::of("DX")}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "exactly one of VALE_CALC, VALE_CALC_I, VALE_CALC_K, VALE, VALE_I must be given (rule "
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
                      {"EXCIT", V::factor({{"CHARGE", V::of(fake("char_meca"))}, {"FONC_MULT", V::of(fake("fonction_sdaster"))}})},
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
        validate("DEFI_CONTACT", {{"MODELE", model}, {"FORMULATION", V::of("XFEM")},
                                  {"ZONE", V::factor({{"FISS_MAIT", crack}, {"COEF_FROT", V::of(0.3)}})}});
        FAIL();
    } catch (const NotImplemented& e) {
        EXPECT_STREQ(e.what(), "keyword ZONE[1]/COEF_FROT is not supported by miniaster (friction is not modelled "
                               "(frictionless contact only))");
    }
    try {
        validate("DEFI_CONTACT", {{"MODELE", model}, {"FORMULATION", V::of("XFEM")},
                                  {"ZONE", V::factor({{"FISS_MAIT", crack}, {"COEF_FROTT", V::of(0.3)}})}});
        FAIL();
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown keyword ZONE[1]/COEF_FROTT for DEFI_CONTACT"), std::string::npos);
    }
    try {
        validate("DEFI_CONTACT", {{"MODELE", model}, {"FORMULATION", V::of("CONTINUE")},
                                  {"ZONE", V::factor({{"FISS_MAIT", crack}})}});
        FAIL();
    } catch (const NotImplemented& e) {
        EXPECT_STREQ(e.what(), "keyword FORMULATION: value 'CONTINUE' is not supported by miniaster");
    }
}

TEST(ParserCatalog, ContextKeywordsOfFormule) {
    CallArguments context;
    const auto* c = Catalog::instance().find("FORMULE");
    auto kw = validateCall(*c, {{"VALE", V::of("depx(X, Y)")}, {"depx", V::of(1LL)}, {"NOM_PARA", V::of("X")}}, &context);
    EXPECT_EQ(kw.texts("NOM_PARA"), std::vector<std::string>{"X"});
    ASSERT_EQ(context.size(), 1u);
    EXPECT_EQ(context[0].first, "depx");
}

// Every entry is consistent: rules name keywords of their level, defaults satisfy `into`,
// names are unique per level (outside blocks), reentrant commands are the documented ones.
namespace {
void checkLevel(const std::string& where, const std::vector<cata::Keyword>& content, const std::vector<cata::Rule>& rules,
                std::set<std::string> names) {
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
                EXPECT_NE(std::find(k.intoTexts.begin(), k.intoTexts.end(), std::get<std::string>(d)), k.intoTexts.end())
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
    EXPECT_EQ(reentrant, (std::set<std::string>{"CALC_TABLE", "DEFI_GROUP", "MECA_STATIQUE", "MODI_MAILLAGE", "STAT_NON_LINE"}));
    EXPECT_GE(Catalog::instance().commands().size(), 28u);
}

// A command file that calls every catalogued command with valid keywords (current and legacy
// syntaxes) is accepted by the validation layer (--check-syntax: nothing is executed).
namespace {
const char* kEveryCommand = R"(
DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET'), DEBUG=_F(SDVERI='OUI'))
PRE_GIBI()
MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20, INFO=1, NOM_MED='mesh', INFO_MED=1, VERI_MAIL=_F(VERIF='OUI', APLAT=1e-3))
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA,
        CREA_GROUP_NO=(_F(NOM='SD', OPTION='PLAN', POINT=(5., 0., 0.), VECT_NORMALE=(1., 0., 0.), PRECISION=0.1),
                       _F(GROUP_MA='LD', CRIT_NOEUD='SOMMET'),
                       _F(NOM='SDG', UNION=('SD', 'SG')), _F(NOM='SI', INTERSEC=('SD', 'SG')),
                       _F(NOM='SM', DIFFE=('SD', 'SG'))),
        CREA_GROUP_MA=(_F(NOM='FACE', OPTION='FACE_NORMALE', VECT_NORMALE=(0, 0, 1), ANGL_PREC=0.5, VERI_SIGNE='OUI'),
                       _F(NOM='SD1', OPTION='BANDE', POINT=(5, 0, 0), VECT_NORMALE=(1, 0, 0), DIST=0.1,
                          CRIT_NOEUD='AU_MOINS_UN'),
                       _F(NOM='SD', INTERSEC=('SD1', 'FACE')), _F(NOM='U', UNION=('SD1', 'FACE')),
                       _F(NOM='D', DIFFE=('SD1', 'FACE'), TYPE_MAILLE='2D')))
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU_3D=_F(GROUP_MA=('ENV', 'SD'), GROUP_MA_VOLU='VOLU'))
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU_2D=_F(GROUP_MA='LD'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(_F(GROUP_MA=('SURF', 'LH'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'),),
                 DISTRIBUTION=_F(METHODE='CENTRALISE'), VERI_JACOBIEN='OUI')
LN1 = FORMULE(VALE='Y', NOM_PARA=['X', 'Y'])
LN2 = FORMULE(VALE='X', NOM_PARA=('X', 'Y'))
F1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1), INFO=1)
F2 = DEFI_FISS_XFEM(MODELE=MO, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN2),
                    JONCTION=_F(FISSURE=F1, POINT=(0, 5)))
MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2), CONTACT='STANDARD', INFO=1)
MX2 = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2), CONTACT='P1P1')
MX3 = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1,), CONTACT='OUI')
CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', ITER_CONT_MAXI=10, ELIM_ARETE='ELIM', REAC_GEOM='SANS',
                  ZONE=(_F(FISS_MAIT=F1, INTEGRATION='NOEUD', CONTACT_INIT='OUI', GLISSIERE='NON',
                           ALGO_CONT='PENALISATION', COEF_PENA_CONT=1.e13),
                        _F(FISS_MAIT=F2, INTEGRATION='GAUSS', ORDRE_INT=3, ALGO_CONT='STANDARD', COEF_CONT=100.)))
CT2 = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', NB_ITER_GEOM=1, REAC_GEOM='CONTROLE',
                   ZONE=_F(FISS_MAIT=F1, ALGO_LAGR='VERSION2', COEF_ECHELLE=1.0))
ACIER = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3, RHO=7800.0, ALPHA=1e-5))
CM = AFFE_MATERIAU(MAILLAGE=MA, MODELE=MX, AFFE=_F(TOUT=('OUI',), MATER=ACIER))
DEPX = FORMULE(VALE='X', NOM_PARA='X')
CH1 = AFFE_CHAR_MECA_F(MODELE=MX, DDL_IMPO=(_F(GROUP_MA=('LD', 'LG'), DX=DEPX, DY=DEPX),
                                           _F(GROUP_NO='SD', DZ=DEPX)),
                       PRES_REP=_F(GROUP_MA='LH', PRES=DEPX), FORCE_INTERNE=_F(TOUT='OUI', FY=DEPX), INFO=1)
CH2 = AFFE_CHAR_MECA(MODELE=MX, DDL_IMPO=(_F(GROUP_MA='LB', DX=0, DY=0, H1X=0, H1Y=0, H2X=0., H4Z=0.),
                                         _F(TOUT='OUI', DZ=0.), _F(NOEUD=('N1',), DX=1.), _F(MAILLE='M1', DY=0)),
                     PRES_REP=_F(TOUT='OUI', PRES=1.e6), FORCE_INTERNE=_F(GROUP_MA='SURF', FX=1., FZ=2))
CH3 = AFFE_CHAR_MECA(MODELE=MX, LIAISON_XFEM='OUI', INFO=1)
CH4 = AFFE_CHAR_MECA(MODELE=MX, CONTACT_XFEM=CT)
VAR1 = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0), INTERPOL='LIN', PROL_GAUCHE='CONSTANT',
                     PROL_DROITE='LINEAIRE', VERIF='CROISSANT', NOM_RESU='TOUTRESU')
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=(_F(JUSQU_A=1, NOMBRE=1), _F(JUSQU_A=2., PAS=0.5)))
L2 = DEFI_LIST_REEL(VALE=(0., 1.))
U1 = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=(_F(CHARGE=CH1), _F(CHARGE=CH2, FONC_MULT=VAR1)), INFO=1)
U1 = MECA_STATIQUE(reuse=U1, MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH2), LIST_INST=L2, OPTION='SIEF_ELGA',
                   SOLVEUR=_F(METHODE='MULT_FRONT', RENUM='METIS', NPREC=8))
U2 = MECA_STATIQUE(MODELE=MX, EXCIT=_F(CHARGE=CH2), INST=1.0, SOLVEUR=_F(METHODE='LDLT'))
U3 = STAT_NON_LINE(MODELE=MX, CHAM_MATER=CM, CONTACT=CT,
                   EXCIT=(_F(CHARGE=CH1, FONC_MULT=VAR1), _F(CHARGE=CH2, TYPE_CHARGE='FIXE_CSTE')),
                   COMPORTEMENT=_F(RELATION='ELAS', GROUP_MA='SURF', DEFORMATION='PETIT'),
                   NEWTON=_F(REAC_INCR=1, REAC_ITER=1, MATRICE='TANGENTE', PREDICTION='ELASTIQUE'),
                   INCREMENT=_F(LIST_INST=L_INST, INST_INIT=0., INST_FIN=1.),
                   CONVERGENCE=_F(ITER_GLOB_MAXI=20, RESI_GLOB_MAXI=1e-6, RESI_GLOB_RELA=1e-6, ARRET='OUI'),
                   SOLVEUR=_F(METHODE='MUMPS', NPREC=-1, PCENT_PIVOT=250, RENUM='AUTO', ELIM_LAGR='NON', RESI_RELA=-1.0),
                   ARCHIVAGE=_F(CHAM_EXCLU='VARI_ELGA', PAS_ARCH=1), INFO=1)
U3 = STAT_NON_LINE(reuse=U3, MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH3),
                   COMP_ELAS=_F(RELATION='ELAS', TOUT='OUI'),
                   INCREMENT=_F(LIST_INST=L_INST, NUME_INST_INIT=0, NUME_INST_FIN=1),
                   CONVERGENCE=_F(ARRET='NON'), SOLVEUR=_F(METHODE='PETSC', PRE_COND='LDLT_INC', RESI_RELA=1e-8),
                   ARCHIVAGE=_F(LIST_INST=L2))
MV = POST_MAIL_XFEM(MODELE=MX, PREF_NOEUD_P='NP', INFO=1)
MOV = AFFE_MODELE(MAILLAGE=MV, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
RX = POST_CHAM_XFEM(MODELE_VISU=MOV, RESULTAT=U3)
RE = POST_CHAM_XFEM(MODELE_VISU=MOV, RESULTAT=U1, INFO=1)
DEP = POST_RELEVE_T(ACTION=(_F(INTITULE='DEPLE', GROUP_NO=('NFISSU',), RESULTAT=RX, NOM_CHAM='DEPL', NUME_ORDRE=1,
                              TOUT_CMP='OUI', OPERATION='EXTRACTION'),
                            _F(INTITULE='D2', NOEUD='N1', RESULTAT=RE, NOM_CHAM='DEPL', INST=1.0, NOM_CMP=('DX', 'DY'),
                              OPERATION='EXTRACTION')))
UC = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=U1, NOM_CHAM='DEPL', NUME_ORDRE=1)
SC = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELGA_SIEF_R', RESULTAT=U3, NOM_CHAM='SIEF_ELGA', INST=1.0,
                CRITERE='ABSOLU', PRECISION=1e-8)
DEP2 = POST_RELEVE_T(ACTION=_F(INTITULE='C', GROUP_NO='SD', CHAM_GD=UC, TOUT_CMP='OUI', OPERATION='EXTRACTION'))
SXX = FORMULE(VALE='-1e6', NOM_PARA=('X', 'Y'))
T1 = POST_ERREUR(OPTION='ENER_RELA', CHAM_GD=SC, MODELE=MX, DEFORMATION='PETIT', CHAM_MATER=CM, GROUP_MA='SURF',
                 SIXX=SXX, SIYY=(SXX,), SIZZ=SXX, SIXY=SXX)
T2 = POST_ERREUR(OPTION='DEPL_RELA', CHAM_GD=UC, MODELE=MX, GROUP_MA=('SURF', 'VOLU'), DX=(DEPX, DEPX), DY=(DEPX, DEPX),
                 CHAM_MATER=CM)
DEP = CALC_TABLE(TABLE=DEP, reuse=DEP, ACTION=_F(OPERATION='EXTR', NOM_PARA=('NOEUD', 'COOR_X', 'COOR_Y', 'DX', 'DY')))
DF = FORMULE(VALE='DX-COOR_X', NOM_PARA=['DX', 'COOR_X'])
Z = [None] * 3
Z[1] = CALC_TABLE(TABLE=DEP, ACTION=(_F(OPERATION='FILTRE', NOM_PARA='NOEUD', CRIT_COMP='REGEXP', VALE_K='NP'),
                                     _F(OPERATION='FILTRE', NOM_PARA='COOR_X', CRIT_COMP='GT', VALE=0.02),
                                     _F(OPERATION='FILTRE', NOM_PARA='COOR_Y', VALE=(0.0, 1.0), CRITERE='ABSOLU',
                                        PRECISION=1e-6),
                                     _F(OPERATION='FILTRE', NOM_PARA='NUME_ORDRE', CRIT_COMP='NE', VALE_I=0),
                                     _F(OPERATION='FILTRE', NOM_PARA='DX', CRIT_COMP='MAXI_ABS'),
                                     _F(OPERATION='COMB', TABLE=DEP2),
                                     _F(OPERATION='COMB', TABLE=DEP2, NOM_PARA='NOEUD', RESTREINT='OUI'),
                                     _F(OPERATION='OPER', FORMULE=DF, NOM_PARA='DX-DX'),
                                     _F(OPERATION='OPER', FORMULE=DF, NOM_PARA='D2', NOM_COLONNE=('DX', 'COOR_Y')),
                                     _F(OPERATION='RENOMME', NOM_PARA=('D2', 'D3')),
                                     _F(OPERATION='TRI', NOM_PARA='DX', ORDRE='DECROISSANT'),
                                     _F(OPERATION='SUPPRIME', NOM_PARA='D3')),
                 TITRE='zone 1')
IMPR_TABLE(TABLE=Z[1])
IMPR_TABLE(TABLE=T1, UNITE=8, FORMAT='TABLEAU', NOM_PARA=('GROUP_MA', 'REFERENCE'), FORMAT_R='E12.5')
TEST_TABLE(TABLE=Z[1], NOM_PARA='DX', TYPE_TEST='MIN', VALE_CALC=-0.25, VALE_REFE=-0.25, CRITERE='RELATIF',
           PRECISION=1e-13, REFERENCE='ANALYTIQUE')
TEST_TABLE(TABLE=T1, NOM_PARA='REFERENCE', VALE_CALC=0., VALE_REFE=0., REFERENCE='ANALYTIQUE',
           FILTRE=_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'))
TEST_TABLE(TABLE=T2, NOM_PARA='ERREUR RELATIVE', CRITERE='ABSOLU', VALE_CALC=9.6e-16, ORDRE_GRANDEUR=1.0,
           FILTRE=(_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'), _F(NOM_PARA='X', VALE=0., CRITERE='ABSOLU'),
                   _F(NOM_PARA='Y', CRIT_COMP='GT', VALE=0.)), LEGENDE='L2', VALE_ABS='NON')
TEST_TABLE(TABLE=T2, NOM_PARA='REFERENCE', VALE=6.8, PRECISION=1e-3, REFERENCE='ANALYTIQUE', VERSION='10.3')
TEST_TABLE(TABLE=T2, NOM_PARA='REFERENCE', VALE=6.8, CRITERE='RELATIF', PRECISION=1e-3)
TEST_TABLE(TABLE=T2, NOM_PARA='REFERENCE', VALE_CALC=6.8, VALE_REFE=6.8, TOLE_MACHINE=2e-4, PRECISION=2e-4,
           REFERENCE='ANALYTIQUE')
TEST_TABLE(TABLE=T2, NOM_PARA='N', VALE_CALC_I=3, TYPE_TEST='SOMM')
TEST_TABLE(TABLE=T2, NOM_PARA='GROUP_MA', VALE_CALC_K='TOTAL', FILTRE=_F(NOM_PARA='N', VALE_I=1))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=(_F(MAILLAGE=MA), _F(RESULTAT=U1, NOM_CHAM=('DEPL', 'SIEF_ELGA'), NUME_ORDRE=1),
                                       _F(RESULTAT=U3, TOUT_ORDRE='OUI'), _F(RESULTAT=RX, INST=1.0),
                                       _F(CHAM_GD=UC), _F(CHAM_GD=SC)))
IMPR_RESU(RESU=_F(RESULTAT=RE))
FIN()
)";
}  // namespace

TEST(ParserCatalog, EveryCommandIsAcceptedBySyntaxCheck) {
    for (const auto& [name, c] : Catalog::instance().commands())
        EXPECT_NE(std::string(kEveryCommand).find(name + "("), std::string::npos) << name << " is not exercised";
    auto r = runComm(kEveryCommand, "--check-syntax");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : SYNTAX_OK (no command executed)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("<F>"), std::string::npos) << r.output;
    EXPECT_FALSE(r.exists("out/t.resu"));  // nothing was run
    EXPECT_NE(r.output.find("Z_1 = CALC_TABLE("), std::string::npos);
    // The run never pretends: the commands were validated, not executed.
    EXPECT_NE(r.output.find("syntax checked; not executed (--check-syntax)"), std::string::npos);
}

// A command file in the syntax of the 2011-2012 versions of ssnv511 (commands_spec §9, old-only
// keywords) passes the syntax check.
TEST(ParserCatalog, LegacySsnv511SyntaxIsAccepted) {
    auto r = runComm(R"(
DEBUT(CODE=_F(NOM='SSNV511E', NIV_PUB_WEB='INTERNET'), PAR_LOT='NON')
PRE_GIBI()
MAILLAG = LIRE_MAILLAGE(INFO=1)
MODELEIN = AFFE_MODELE(MAILLAGE=MAILLAG, AFFE=_F(GROUP_MA=('SURF', 'LH', 'LD'), PHENOMENE='MECANIQUE',
                                                 MODELISATION='D_PLAN'))
LN1 = FORMULE(VALE='Y', NOM_PARA=('X', 'Y'))
FISS1 = DEFI_FISS_XFEM(MODELE=MODELEIN, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1), INFO=1)
MODELEK = MODI_MODELE_XFEM(MODELE_IN=MODELEIN, FISSURE=FISS1, CONTACT='P1P1', INFO=1)
CTXFEM = DEFI_CONTACT(MODELE=MODELEK, FORMULATION='XFEM', ITER_CONT_MAXI=10, NB_ITER_GEOM=1,
                      ZONE=_F(FISS_MAIT=FISS1, INTEGRATION='GAUSS', CONTACT_INIT='OUI', ALGO_LAGR='VERSION2',
                              COEF_ECHELLE=1.0, GLISSIERE='NON'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3, RHO=7800.0))
CHAMPMAT = AFFE_MATERIAU(MAILLAGE=MAILLAG, MODELE=MODELEK, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH1 = AFFE_CHAR_MECA(MODELE=MODELEK, LIAISON_XFEM='OUI', DDL_IMPO=_F(GROUP_MA='LB', DY=0, H1Y=0), INFO=1)
CH2 = AFFE_CHAR_MECA(MODELE=MODELEK, CONTACT_XFEM=CTXFEM)
VAR1 = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
UTOT1 = STAT_NON_LINE(MODELE=MODELEK, CHAM_MATER=CHAMPMAT, CONTACT=CTXFEM,
                      EXCIT=(_F(CHARGE=CH1, FONC_MULT=VAR1), _F(CHARGE=CH2)),
                      COMP_ELAS=_F(RELATION='ELAS', GROUP_MA='SURF'),
                      INCREMENT=_F(LIST_INST=L_INST),
                      CONVERGENCE=_F(ITER_GLOB_MAXI=20, RESI_GLOB_MAXI=1e-6, ARRET='NON'),
                      SOLVEUR=_F(METHODE='MUMPS', PCENT_PIVOT=250, NPREC=-1), INFO=1)
MA_XFEM = POST_MAIL_XFEM(MODELE=MODELEK)
MOD_VISU = AFFE_MODELE(MAILLAGE=MA_XFEM, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
RES_XFEM = POST_CHAM_XFEM(MODELE_VISU=MOD_VISU, RESULTAT=UTOT1)
DEP = POST_RELEVE_T(ACTION=_F(INTITULE='DEPLE', GROUP_NO=('NFISSU',), RESULTAT=RES_XFEM, NOM_CHAM='DEPL',
                              TOUT_CMP='OUI', OPERATION='EXTRACTION'))
vale = [0, -0.25, -0.5, 0.75, 1]
preci = 1e-13
for i in [1, 2]:
    TEST_TABLE(TABLE=DEP, NOM_PARA='DX', TYPE_TEST='MIN', VALE=vale[i], CRITERE='RELATIF', PRECISION=preci,
               REFERENCE='ANALYTIQUE')
    TEST_TABLE(TABLE=DEP, NOM_PARA='DY', TYPE_TEST='MAX', VALE_CALC=0., VALE_REFE=vale[0], TOLE_MACHINE=2e-4,
               PRECISION=preci, CRITERE='ABSOLU', REFERENCE='ANALYTIQUE')
TEST_TABLE(TABLE=DEP, NOM_PARA='DX', TYPE_TEST='MAX', VALE=1.0, REFERENCE='NON_REGRESSION', VERSION='10.3')
FIN()
)",
                     "--check-syntax");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("<F>"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("CONTACT='STANDARD'"), std::string::npos);  // 'P1P1' read as the current value
    EXPECT_NE(r.output.find("PRE_GIBI is a no-op in miniaster"), std::string::npos);
}
