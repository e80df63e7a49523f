// FORMULE in process: batch evaluation and errors naming formula, values and line (FORMULE in a
// command file run by the binary: tests/cli/parser_formula_runs.cpp).
#include <gtest/gtest.h>
#include <pybind11/embed.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "parser/Formula.hpp"

namespace py = pybind11;

namespace {
// One interpreter for the whole test program, never finalised: like the real run (numpy and the
// formula support module cannot survive an interpreter restart).
void ensurePython() { static auto* interpreter = new py::scoped_interpreter(); (void)interpreter; }
}  // namespace

// Batch evaluation in-process: one entry into Python for all points, values and failures.
TEST(ParserFormula, EvaluateManyInOneBatch) {
    ensurePython();
    py::dict context;
    context["shift"] = py::float_(0.5);
    py::dict globals;
    globals["k"] = py::float_(3.0);
    ma::Formula f("k*X + Y*Y + shift + atan2(0, 1)", {"X", "Y"}, context, globals, "/tmp/x.comm", 12);
    f.name = "FXY";
    const size_t n = 10000;
    std::vector<double> args(2 * n);
    for (size_t i = 0; i < n; ++i) {
        args[2 * i] = double(i);
        args[2 * i + 1] = 0.5 * double(i);
    }
    auto values = f.evaluateMany(args, n);
    ASSERT_EQ(values.size(), n);
    for (size_t i = 0; i < n; i += 997) EXPECT_DOUBLE_EQ(values[i], 3.0 * i + 0.25 * i * i + 0.5);
    std::map<std::string, std::vector<double>> columns{{"X", {1.0, 2.0}}, {"Y", {0.0, 1.0}}, {"Z", {9.0, 9.0}}};
    EXPECT_EQ(f.evaluateColumns(columns, 2), (std::vector<double>{3.5, 7.5}));

    ma::Formula g("1.0/(X - 2.0)", {"X"}, py::dict(), py::dict(), "/tmp/x.comm", 7);
    g.name = "G";
    std::vector<double> xs{0.0, 1.0, 2.0, 3.0};
    try {
        g.evaluateMany(xs, 4);
        FAIL();
    } catch (const ma::UserError& e) {
        EXPECT_STREQ(e.what(), "formula G = '1.0/(X - 2.0)' (FORMULE defined in x.comm, line 7) failed for X=2: "
                               "ZeroDivisionError: float division by zero");
    }
    ma::Formula h("log(X)", {"X"}, py::dict(), py::dict(), "/tmp/x.comm", 8);
    h.name = "H";
    std::vector<double> one{0.0};
    EXPECT_THROW(h.evaluateMany(one, 1), ma::UserError);  // math domain error
    EXPECT_THROW(ma::Formula("X +", {"X"}, py::dict(), py::dict(), "x.comm", 1), ma::UserError);
    EXPECT_THROW(ma::Formula("X", {"X Y"}, py::dict(), py::dict(), "x.comm", 1), ma::UserError);
}

// Large batches go through numpy as whole arrays; expressions numpy cannot take (user functions
// with `if`, math names without a numpy twin) fall back to the point loop, and so does a batch
// with a non-finite value, so that the error names the point and Python's own message.
TEST(ParserFormula, VectorisedBatchesAgreeWithThePointLoop) {
    ensurePython();
    py::dict globals;
    py::exec("def depx(x, y):\n    if y > 0 and x < 0: return -0.25\n    return 1.0\n", globals);
    const size_t n = 1000;
    std::vector<double> args(2 * n);
    for (size_t i = 0; i < n; ++i) {
        args[2 * i] = -5.0 + 10.0 * double(i) / n;
        args[2 * i + 1] = 5.0 - 7.0 * double(i) / n;
    }
    for (const char* expression : {"X*Y - 3*X**2 + Y/7", "sin(X)*cos(Y) + exp(X/5) + sqrt(X*X + 1) + atan2(Y, X)",
                                   "depx(X, Y) * 2", "floor(X) + log(X*X + 1)", "2.5"}) {
        ma::Formula f(expression, {"X", "Y"}, py::dict(), globals, "/tmp/x.comm", 3);
        auto batch = f.evaluateMany(args, n);
        ASSERT_EQ(batch.size(), n) << expression;
        for (size_t i = 0; i < n; ++i) {
            const double single = f.evaluate(std::span<const double>(args).subspan(2 * i, 2));
            EXPECT_NEAR(batch[i], single, 4e-16 * std::max(1.0, std::abs(single))) << expression << " at " << i;
        }
    }
    ma::Formula g("1.0/(X - 2.0)", {"X"}, py::dict(), py::dict(), "/tmp/x.comm", 7);
    g.name = "G";
    std::vector<double> xs(100);
    for (size_t i = 0; i < xs.size(); ++i) xs[i] = double(i) * 0.5;
    try {
        g.evaluateMany(xs, xs.size());
        FAIL();
    } catch (const ma::UserError& e) {
        EXPECT_STREQ(e.what(), "formula G = '1.0/(X - 2.0)' (FORMULE defined in x.comm, line 7) failed for X=2: "
                               "ZeroDivisionError: float division by zero");
    }
}
