#pragma once
// Functions of named real parameters: FORMULE (Python expression, parser/Formula*) and
// DEFI_FONCTION (tabulated, src/core/TabulatedFunction*). Callers supply parameter values by name
// (X, Y, Z, INST, table columns...) and evaluate many points in one call, so that Python formulas
// are entered once per batch, not once per point.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/Concept.hpp"

namespace ma {

class Function : public Concept {
public:
    // NOM_PARA, in order.
    virtual const std::vector<std::string>& parameters() const = 0;
    // One evaluation; args in the order of parameters(). NumericalError/UserError on failure
    // (the message names the function and the argument values).
    virtual double evaluate(std::span<const double> args) const = 0;
    // `args` is point-major: npoints * parameters().size(). Default: loop over evaluate().
    virtual std::vector<double> evaluateMany(std::span<const double> args, size_t npoints) const;

    // Evaluate at npoints points given named columns (each of size npoints). Every parameter of
    // the function must be among the columns, otherwise UserError naming the missing parameter.
    std::vector<double> evaluateColumns(const std::map<std::string, std::vector<double>>& columns,
                                        size_t npoints) const;
};

// DEFI_FONCTION: piecewise-linear interpolation of (x, y) pairs.
class TabulatedFunction : public Function {
public:
    std::string typeName() const override { return "fonction_sdaster"; }
    const std::vector<std::string>& parameters() const override { return parameter_; }
    double evaluate(std::span<const double> args) const override;

    std::vector<std::string> parameter_{"INST"};
    std::vector<double> x, y;
    // PROL_GAUCHE / PROL_DROITE: 'E' exclu (error), 'C' constant, 'L' linear.
    char leftExtension = 'E', rightExtension = 'E';
};

// DEFI_CONSTANTE: the same value for any parameters (code_aster's NOM_PARA 'TOUTPARA'), so it
// has none and takes any arguments.
class ConstantFunction : public Function {
public:
    std::string typeName() const override { return "fonction_sdaster"; }
    const std::vector<std::string>& parameters() const override { return none_; }
    double evaluate(std::span<const double>) const override { return value; }
    double value = 0.0;

private:
    std::vector<std::string> none_;
};

// DEFI_LIST_REEL.
class RealList : public Concept {
public:
    std::string typeName() const override { return "listr8_sdaster"; }
    std::vector<double> values;
};

}  // namespace ma
