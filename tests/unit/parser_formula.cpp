// FORMULE in process: batch evaluation and errors naming formula, values and line (FORMULE in a
// command file run by the binary: tests/cli/parser_formula_runs.cpp).
#include <gtest/gtest.h>
#include <pybind11/embed.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "parser/Formula.hpp"

namespace py = pybind11;

namespace {
// One interpreter for the whole test program, never finalised: like the real run (numpy and the
// formula support module cannot survive an interpreter restart).
void ensurePython() {
    static auto* interpreter = new py::scoped_interpreter();
    (void)interpreter;
}
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
    for (size_t i = 0; i < n; i += 997) {
        const double x = static_cast<double>(i);
        EXPECT_DOUBLE_EQ(values[i], 3.0 * x + 0.25 * x * x + 0.5);
    }
    std::map<std::string, std::vector<double>> columns{{"X", {1.0, 2.0}}, {"Y", {0.0, 1.0}}, {"Z", {9.0, 9.0}}};
    EXPECT_EQ(f.evaluateColumns(columns, 2), (std::vector<double>{3.5, 7.5}));

    ma::Formula g("1.0/(X - 2.0)", {"X"}, py::dict(), py::dict(), "/tmp/x.comm", 7);
    g.name = "G";
    std::vector<double> xs{0.0, 1.0, 2.0, 3.0};
    try {
        g.evaluateMany(xs, 4);
        FAIL();
    } catch (const ma::UserError& e) {
        EXPECT_STREQ(e.what(),
                     "formula G = '1.0/(X - 2.0)' (FORMULE defined in x.comm, line 7) failed for X=2: "
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
        EXPECT_STREQ(e.what(),
                     "formula G = '1.0/(X - 2.0)' (FORMULE defined in x.comm, line 7) failed for X=2: "
                     "ZeroDivisionError: float division by zero");
    }
}

// A Python if/else no longer sends a batch point by point: the points are split by each condition
// whose truth differs between them and every branch runs on arrays (same values as the scalar
// calls, bit for bit: + - * / are the same IEEE operations). The .mess says which path was taken.
TEST(ParserFormula, BranchingFunctionsRunOnArrays) {
    ensurePython();
    ma::msg().setEcho(false);
    py::dict globals;
    py::exec(R"(
def pres(s):
    if s < 0.:
        return 1.0e6
    return 2.0e6
def eps(x, y):
    return 1.3e-8 * (0.7 * -pres(y) - 0.3 * -pres(x))
def ux(x, y):
    if x < 0.:
        return eps(x, y) * (x + 5.)
    return eps(-1., y) * 5. + eps(x, y) * x
def clipped(x, y):
    return max(min(x, 1.), -1.) + (y if y > 0 else 0)
)",
             globals);
    const size_t n = 4000;
    std::vector<double> args(2 * n);
    for (size_t i = 0; i < n; ++i) {
        args[2 * i] = -5.0 + 10.0 * double(i) / n;
        args[2 * i + 1] = 5.0 - 10.0 * double((i * 7919) % n) / n;
    }
    struct Case {
        const char* expression;
        int branches;
    };
    for (const auto& c : {Case{"ux(X, Y)", 4}, Case{"clipped(X, Y)", 4}}) {
        ma::Formula f(c.expression, {"X", "Y"}, py::dict(), globals, "/tmp/x.comm", 3);
        f.name = "F";
        const auto batch = f.evaluateMany(args, n);
        for (size_t i = 0; i < n; ++i)
            ASSERT_EQ(batch[i], f.evaluate(std::span<const double>(args).subspan(2 * i, 2)))
                << c.expression << " " << i;
        EXPECT_NE(ma::msg().messText().rfind(
                      fmt::format("FORMULE F: evaluated on numpy arrays, 4000 points per batch (its "
                                  "conditions split the points into {} branches",
                                  c.branches)),
                  std::string::npos)
            << c.expression << "\n"
            << ma::msg().messText();
    }
}

// What arrays cannot stand for: a function that is not evaluated point by point on arrays (here a
// mean over the batch) is caught by the check of each branch against the scalar call, and a
// function numpy cannot take (math.floor) is called once per distinct point, not per point.
TEST(ParserFormula, NonElementwiseFunctionsFallBackToDistinctPoints) {
    ensurePython();
    ma::msg().setEcho(false);
    py::dict globals;
    py::exec(R"(
import math, numpy
calls = [0]
def centred(x):
    return x - numpy.mean(x)
def stepped(x):
    if isinstance(x, float):
        calls[0] += 1
    return math.floor(x) * 0.5
)",
             globals);
    const size_t n = 3000;
    std::vector<double> xs(n);
    for (size_t i = 0; i < n; ++i) xs[i] = double(i % 100) * 0.25;  // 100 distinct points
    ma::Formula centred("centred(X)", {"X"}, py::dict(), globals, "/tmp/x.comm", 4);
    for (double v : centred.evaluateMany(xs, n)) ASSERT_EQ(v, 0.0);
    ma::Formula stepped("stepped(X)", {"X"}, py::dict(), globals, "/tmp/x.comm", 5);
    stepped.name = "STEP";
    const auto values = stepped.evaluateMany(xs, n);
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(values[i], std::floor(xs[i]) * 0.5);
    EXPECT_EQ(globals["calls"].cast<py::list>()[0].cast<int>(), 100);
    EXPECT_NE(ma::msg().messText().rfind(
                  "FORMULE STEP: numpy arrays do not go through its expression: Python is called "
                  "once per distinct point (100 of 3000 points in the first batch)"),
              std::string::npos)
        << ma::msg().messText();
}
