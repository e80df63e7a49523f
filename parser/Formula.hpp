#pragma once
// FORMULE: a function whose value is a Python expression of its parameters (commands_spec §7.4).
// The expression is compiled once; evaluateMany() enters Python once per batch, which runs on
// numpy arrays when the expression allows it (a Python if/else included: the points are split by
// its conditions) and otherwise calls Python once per distinct point; the .mess says which. Names are looked
// up in: parameters, the context objects given as extra keywords (depx=depx), the math module,
// then (files older than 2018 do not pass their functions) the globals of the command file.
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "core/Function.hpp"

namespace ma {

class Formula : public Function {
public:
    // `context`: the extra keywords of FORMULE; `commGlobals`: the command file's namespace.
    // Throws UserError when the expression does not compile or a parameter name is invalid.
    Formula(std::string expression, std::vector<std::string> parameters, pybind11::dict context,
            pybind11::dict commGlobals, std::string commFile, int line);
    ~Formula() override;

    std::string typeName() const override { return "formule"; }
    const std::vector<std::string>& parameters() const override { return parameters_; }
    double evaluate(std::span<const double> args) const override;
    std::vector<double> evaluateMany(std::span<const double> args, size_t npoints) const override;

    const std::string& expression() const { return expression_; }
    int definitionLine() const { return line_; }

private:
    [[noreturn]] void fail(std::span<const double> args, const std::string& why) const;
    // .mess line when a batch takes another path than the previous one ("vector" / "points").
    void logPath(const std::string& path, size_t npoints) const;
    static constexpr size_t kBatchLogged = 16;  // smaller batches: single points, not worth a line

    std::string expression_;
    std::vector<std::string> parameters_;
    std::string commFile_;
    int line_ = 0;
    mutable std::string loggedPath_;
    struct Python;  // compiled expression, batch evaluator, name scope (Formula.cpp)
    std::unique_ptr<Python> python_;
};

}  // namespace ma
