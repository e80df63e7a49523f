// Number formats of code_aster's printers (commands_spec.md §1.5.5, §4.2).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "core/FortranFormat.hpp"
#include "post/PythonFormat.hpp"
#include "post/TableOperations.hpp"

using namespace ma;

TEST(PythonRepr, FixedNotationRange) {
    EXPECT_EQ(pythonRepr(1397500.0), "1397500.0");
    EXPECT_EQ(pythonRepr(-0.25), "-0.25");
    EXPECT_EQ(pythonRepr(0.0), "0.0");
    EXPECT_EQ(pythonRepr(-0.0), "-0.0");
    EXPECT_EQ(pythonRepr(0.0001), "0.0001");
    EXPECT_EQ(pythonRepr(0.1), "0.1");
    EXPECT_EQ(pythonRepr(1e-3 * 100), "0.1");
    EXPECT_EQ(pythonRepr(1e15), "1000000000000000.0");
    EXPECT_EQ(pythonRepr(9999999999999998.0), "9999999999999998.0");
    EXPECT_EQ(pythonRepr(6.846531968814576), "6.846531968814576");
    EXPECT_EQ(pythonRepr(0.791204250915443), "0.791204250915443");
    EXPECT_EQ(pythonRepr(123.456), "123.456");
    EXPECT_EQ(pythonRepr(999.999999), "999.999999");
}

TEST(PythonRepr, ScientificNotation) {
    EXPECT_EQ(pythonRepr(1e-5), "1e-05");
    EXPECT_EQ(pythonRepr(1e16), "1e+16");
    EXPECT_EQ(pythonRepr(1.5e300), "1.5e+300");
    EXPECT_EQ(pythonRepr(2.6562953225895e-17), "2.6562953225895e-17");
    EXPECT_EQ(pythonRepr(-1.0347625534202e-15), "-1.0347625534202e-15");
    EXPECT_EQ(pythonRepr(DBL_MAX), "1.7976931348623157e+308");
    EXPECT_EQ(pythonRepr(5e-324), "5e-324");
    EXPECT_EQ(pythonRepr(INFINITY), "inf");
    EXPECT_EQ(pythonRepr(-INFINITY), "-inf");
    EXPECT_EQ(pythonRepr(NAN), "nan");
}

TEST(TestValueText, UppercaseExponentAndShortestDigits) {
    EXPECT_EQ(testValueText(1e-6 * 100), "9.999999999999999E-05");
    EXPECT_EQ(testValueText(1e-13 * 100), "1.0000000000000001E-11");
    EXPECT_EQ(testValueText(1e-6), "1E-06");
    EXPECT_EQ(testValueText(1e-13), "1E-13");
    EXPECT_EQ(testValueText(1e-300), "1E-300");
}

TEST(PrintfReal, PythonPercentE) {
    EXPECT_EQ(printfReal("%12.5E", -0.25), "-2.50000E-01");
    EXPECT_EQ(printfReal("%12.5E", 1.0), " 1.00000E+00");
    EXPECT_EQ(printfReal("%12.5E", 0.0), " 0.00000E+00");
    EXPECT_EQ(printfReal("%12.5E", 1e-300), "1.00000E-300");
    EXPECT_EQ(printfReal("%13.6e", 1.0347625534202e-15), " 1.034763e-15");
}

TEST(FortranFormat, ToPrintf) {
    EXPECT_EQ(fortranToPrintf("E12.5"), "%12.5E");
    EXPECT_EQ(fortranToPrintf("D15.8"), "%15.8E");
    EXPECT_EQ(fortranToPrintf("F10.3"), "%10.3f");
    EXPECT_EQ(fortranToPrintf("G14.7"), "%14.7G");
    EXPECT_THROW(fortranToPrintf("X12"), std::exception);
    EXPECT_THROW(fortranToPrintf("E"), std::exception);
    // a scale factor: code_aster's fmtF2PY puts as many blanks before the value
    EXPECT_EQ(fortranToPrintf("1PE12.5"), " %12.5E");
    EXPECT_EQ(fortranToPrintf("2PD15.8"), "  %15.8E");
    EXPECT_EQ(fortranFormatProblem("1PE12.5"), "");
    EXPECT_NE(fortranFormatProblem("PE12.5"), "");
    EXPECT_NE(fortranFormatProblem("1PX12"), "");
    EXPECT_NE(fortranFormatProblem("E12.5.3"), "");
}
