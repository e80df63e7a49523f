// FORMULE in a command file run by the binary: parameters as string / list / tuple, context
// objects, math names, the legacy fallback to the command file's globals, true division, and a
// wrong number of arguments reported as a Python error with its line.
#include <gtest/gtest.h>

#include <string>

#include "parser_run.hpp"

using ma::test::runComm;

TEST(ParserFormula, EvaluationFromTheCommandFile) {
    auto r = runComm(R"(
DEBUT()
def depx(x, y):
    if y > 0 and x < 0: return -0.25
    return 1
def uy(x): return 2*x
F1 = FORMULE(VALE='X*Y+1', NOM_PARA='X')
F2 = FORMULE(VALE='X*Y', NOM_PARA=['X', 'Y'])
F3 = FORMULE(VALE='''X +
                     Y''', NOM_PARA=('X', 'Y'))
F4 = FORMULE(VALE='depx(X, Y)', depx=depx, NOM_PARA=['X', 'Y'])
F5 = FORMULE(VALE='uy(X) + pressure', uy=uy, pressure=10., NOM_PARA='X')
F6 = FORMULE(VALE='sin(pi/2) + sqrt(X) + exp(0) + cos(0)', NOM_PARA='X')
F7 = FORMULE(VALE='depx(X, Y)*3', NOM_PARA=('X', 'Y'))
F8 = FORMULE(VALE='7/2', NOM_PARA='X')
Y = 5.
print("F1", repr(F1(2)))
print("F2", repr(F2(2., 3)))
print("F3", repr(F3(2., 3.)))
print("F4", repr(F4(-1., 1.)), repr(F4(1., 1.)))
print("F5", repr(F5(2.)))
print("F6", repr(F6(4.)))
print("F7", repr(F7(-1., 1.)))
print("F8", repr(F8(0.)))
FIN()
)");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("\nF1 11.0\n"), std::string::npos) << r.output;  // Y from the file's globals
    EXPECT_NE(r.output.find("\nF2 6.0\n"), std::string::npos);
    EXPECT_NE(r.output.find("\nF3 5.0\n"), std::string::npos);
    EXPECT_NE(r.output.find("\nF4 -0.25 1.0\n"), std::string::npos);
    EXPECT_NE(r.output.find("\nF5 14.0\n"), std::string::npos);
    EXPECT_NE(r.output.find("\nF6 5.0\n"), std::string::npos);
    EXPECT_NE(r.output.find("\nF7 -0.75\n"), std::string::npos);  // pre-2018: depx not passed
    EXPECT_NE(r.output.find("\nF8 3.5\n"), std::string::npos);    // true division
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : OK"), std::string::npos);
}

TEST(ParserFormula, WrongNumberOfArgumentsIsAPythonError) {
    auto r = runComm("DEBUT()\nF = FORMULE(VALE='X', NOM_PARA=('X', 'Y'))\nv = F(1.)\n");
    ma::test::expectError(r,
                          "<F> <ERROR> (t.comm, line 3): error in the Python code of the command file: TypeError: "
                          "F() takes 2 argument(s) (X, Y), got 1");
}
