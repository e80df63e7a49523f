// Each class of bad command-file input gives one exact error paragraph naming the command, the
// keyword path, the value and the .comm line; exit status 1; no result file left behind.
#include <gtest/gtest.h>

#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "parser_run.hpp"

using namespace ma::test;

TEST(ParserErrors, UnknownCommand) {
    auto r = runComm("DEBUT()\nA = FOO_BAR(X=1)\nFIN()\n");
    expectError(
        r,
        "<F> <ERROR> FOO_BAR (t.comm, line 2): unknown command FOO_BAR (not a code_aster command known to miniaster)");
}

TEST(ParserErrors, UndefinedVariableInCapitals) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., EMAX))\n");
    expectError(r,
                "<F> <ERROR> (t.comm, line 2): error in the Python code of the command file: NameError: name 'EMAX' "
                "is not defined");
}

TEST(ParserErrors, CodeAsterCommandNotSupported) {
    auto r = runComm("DEBUT()\nA = PROPA_FISS(RESULTAT=None)\nFIN()\n");
    expectError(r, "<F> <ERROR> PROPA_FISS (t.comm, line 2): command PROPA_FISS is not supported by miniaster");
}

TEST(ParserErrors, UnknownKeyword) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 1.),\n   PASS=1)\nFIN()\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): unknown keyword PASS for DEFI_LIST_REEL (known "
                "keywords: DEBUT, INFO, INTERVALLE, TITRE, VALE)");
}

TEST(ParserErrors, UnknownKeywordInFactor) {
    auto r = runComm(
        "DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=(_F(JUSQU_A=1., NOMBRE=2), _F(JUSQU_A=2., NOMBR=2)))\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): unknown keyword INTERVALLE[2]/NOMBR for "
                "DEFI_LIST_REEL (known keywords in INTERVALLE[2]: JUSQU_A, NOMBRE, PAS)");
}

TEST(ParserErrors, UnsupportedKeyword) {
    auto r = runComm("DEBUT()\nC = DEFI_CONTACT(FORMULATION='XFEM', ITER_FROT_MAXI=3, ZONE=_F())\n");
    expectError(r,
                "<F> <ERROR> DEFI_CONTACT (t.comm, line 2): keyword ITER_FROT_MAXI is not supported by miniaster "
                "(friction is not modelled (frictionless contact only))");
}

TEST(ParserErrors, UnsupportedValue) {
    auto r = runComm("DEBUT()\nF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0, 0, 1, 1), INTERPOL='LOG')\n");
    expectError(
        r, "<F> <ERROR> DEFI_FONCTION (t.comm, line 2): keyword INTERPOL: value 'LOG' is not supported by miniaster");
}

TEST(ParserErrors, WrongType) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 'a'))\n");
    expectError(r, "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): keyword VALE: 'a' is not of type real");
}

TEST(ParserErrors, WrongTypeIntegerInFactor) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=2.5))\n");
    expectError(
        r, "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): keyword INTERVALLE[1]/NOMBRE: 2.5 is not of type integer");
}

TEST(ParserErrors, WrongConceptType) {
    auto r = runComm(
        "DEBUT()\nF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0, 0, 1, 1))\n"
        "M = AFFE_MODELE(MAILLAGE=F, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))\n");
    expectError(r,
                "<F> <ERROR> AFFE_MODELE (t.comm, line 3): keyword MAILLAGE: F (fonction_sdaster) is not of type "
                "maillage_sdaster");
}

TEST(ParserErrors, ValueNotAllowed) {
    auto r = runComm("DEBUT()\nF = DEFI_FONCTION(NOM_PARA='INST', VALE=(0, 0, 1, 1), PROL_GAUCHE='LINEAR')\n");
    expectError(r,
                "<F> <ERROR> DEFI_FONCTION (t.comm, line 2): keyword PROL_GAUCHE: value 'LINEAR' is not allowed "
                "(allowed values: 'CONSTANT', 'LINEAIRE', 'EXCLU')");
}

TEST(ParserErrors, TooManyValues) {
    auto r = runComm("DEBUT()\nF = DEFI_FONCTION(NOM_PARA=('INST', 'X'), VALE=(0, 0, 1, 1))\n");
    expectError(r,
                "<F> <ERROR> DEFI_FONCTION (t.comm, line 2): keyword NOM_PARA accepts at most 1 value, got 2: "
                "('INST', 'X')");
}

TEST(ParserErrors, MissingMandatoryKeyword) {
    auto r = runComm("DEBUT()\nF = DEFI_FONCTION(VALE=(0, 0, 1, 1))\n");
    expectError(r, "<F> <ERROR> DEFI_FONCTION (t.comm, line 2): mandatory keyword NOM_PARA is missing");
}

TEST(ParserErrors, MissingMandatoryKeywordInFactor) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(NOMBRE=2))\n");
    expectError(r, "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): mandatory keyword INTERVALLE[1]/JUSQU_A is missing");
}

TEST(ParserErrors, RuleViolation) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 1.), DEBUT=0.)\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): exactly one of VALE, DEBUT must be given (rule "
                "UN_PARMI), got VALE, DEBUT");
}

TEST(ParserErrors, RuleViolationInFactor) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=2, PAS=0.5))\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): exactly one of NOMBRE, PAS must be given in "
                "INTERVALLE[1] (rule UN_PARMI), got NOMBRE, PAS");
}

TEST(ParserErrors, KeywordOfAnInactiveBlock) {
    auto r =
        runComm("DEBUT()\nT = CALC_TABLE(TABLE=None, ACTION=_F(OPERATION='EXTR', NOM_PARA='DX', CRIT_COMP='GT'))\n");
    expectError(r,
                "<F> <ERROR> CALC_TABLE (t.comm, line 2): keyword ACTION[1]/CRIT_COMP is not allowed here: it is "
                "only accepted when OPERATION='FILTRE'");
    auto r2 = runComm(
        "DEBUT()\nL = DEFI_LIST_REEL(VALE=(0.,1.))\nT = CALC_TABLE(TABLE=L, ACTION=_F(OPERATION='EXTR', "
        "NOM_PARA='DX', CRIT_COMP='GT'))\n");
    expectError(
        r2, "<F> <ERROR> CALC_TABLE (t.comm, line 3): keyword TABLE: L (listr8_sdaster) is not of type table_sdaster");
}

TEST(ParserErrors, ReuseOfNonReentrantCommand) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 1.))\nL = DEFI_LIST_REEL(reuse=L, VALE=(0., 2.))\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 3): reuse= is not allowed: DEFI_LIST_REEL is not a "
                "reentrant command");
}

TEST(ParserErrors, PositionalArguments) {
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL((0., 1.))\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): DEFI_LIST_REEL takes keyword arguments only (got 1 "
                "positional argument)");
}

TEST(ParserErrors, PythonSyntaxError) {
    auto r = runComm("DEBUT()\n\nA = = 2\nFIN()\n");
    expectError(r, "<F> <SYNTAX_ERROR> (t.comm, line 3): Python syntax error: invalid syntax: `A = = 2`",
                "<F>_SYNTAX_ERROR");
}

TEST(ParserErrors, PythonExceptionInUserCode) {
    auto r = runComm("DEBUT()\nx = [1, 2]\ny = x[5]\nFIN()\n");
    expectError(r,
                "<F> <ERROR> (t.comm, line 3): error in the Python code of the command file: IndexError: list index "
                "out of range");
}

TEST(ParserErrors, FormulaRaises) {
    auto r =
        runComm("DEBUT()\nF = FORMULE(VALE='1./(X-Y)', NOM_PARA=('X', 'Y'))\nprint(F(1., 2.))\nv = F(2., 2.)\nFIN()\n");
    expectError(r,
                "<F> <ERROR> F (t.comm, line 4): formula F = '1./(X-Y)' (FORMULE defined in t.comm, line 2) failed "
                "for X=2, Y=2: ZeroDivisionError: float division by zero");
}

TEST(ParserErrors, FormulaReturnsNaN) {
    auto r = runComm("DEBUT()\n\nF = FORMULE(VALE='X*inf', NOM_PARA='X')\nv = F(0.)\n");
    expectError(r,
                "<F> <ERROR> F (t.comm, line 4): formula F = 'X*inf' (FORMULE defined in t.comm, line 3) failed for "
                "X=0: the result is nan");
}

TEST(ParserErrors, FormulaUnknownName) {
    auto r = runComm("DEBUT()\nF = FORMULE(VALE='depx(X)', NOM_PARA='X')\nv = F(1.)\n");
    expectError(r,
                "<F> <ERROR> F (t.comm, line 3): formula F = 'depx(X)' (FORMULE defined in t.comm, line 2) failed "
                "for X=1: NameError: name 'depx' is not defined");
}

TEST(ParserErrors, FormulaNotAnExpression) {
    auto r = runComm("DEBUT()\nF = FORMULE(VALE='X +', NOM_PARA='X')\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find(
                  "<F> <ERROR> FORMULE (t.comm, line 2): FORMULE: VALE 'X +' is not a valid Python expression"),
              std::string::npos)
        << r.output;
}

TEST(ParserErrors, MissingFileInExport) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    writeText(dir / "t.export", "P time_limit 30\nF comm t.comm D 1\nF mmed missing.mmed D 20\n");
    auto r = runMiniaster(dir, "t.export");
    const auto missing = (std::filesystem::absolute(dir) / "missing.mmed").string();
    expectError(r, "<F> <ERROR> t.export, line 3: the data file " + missing +
                       " of unit 20 does not exist (F mmed missing.mmed D 20)");
}

TEST(ParserErrors, CommandNotImplementedYet) {
    // A catalogued command without a registered implementation stops the run (never pretends).
    // MINIASTER_UNREGISTER hides an implementation, whatever the state of the other commands.
    auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 1.))\nFIN()\n", "", "MINIASTER_UNREGISTER=DEFI_LIST_REEL");
    expectError(r, "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): DEFI_LIST_REEL is not implemented yet in miniaster");
}
