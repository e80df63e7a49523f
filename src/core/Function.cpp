#include "core/Function.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"

namespace ma {

std::vector<double> Function::evaluateMany(std::span<const double> args, size_t npoints) const {
    const size_t np = parameters().size();
    std::vector<double> out(npoints);
    for (size_t i = 0; i < npoints; ++i) out[i] = evaluate(args.subspan(i * np, np));
    return out;
}

std::vector<double> Function::evaluateColumns(const std::map<std::string, std::vector<double>>& columns,
                                              size_t npoints) const {
    const auto& params = parameters();
    std::vector<const std::vector<double>*> cols;
    for (const auto& p : params) {
        auto it = columns.find(p);
        if (it == columns.end()) {
            std::string available;
            for (const auto& [k, v] : columns) {
                if (!available.empty()) available += ", ";
                available += k;
            }
            throw UserError(
                fmt::format("function {} needs parameter {}, which is not available here "
                            "(available: {})",
                            name, p, available));
        }
        cols.push_back(&it->second);
    }
    std::vector<double> args(npoints * params.size());
    for (size_t i = 0; i < npoints; ++i)
        for (size_t j = 0; j < params.size(); ++j) args[i * params.size() + j] = (*cols[j])[i];
    return evaluateMany(args, npoints);
}

double TabulatedFunction::evaluate(std::span<const double> args) const {
    if (args.size() != 1 || x.empty()) throw UserError("function " + name + " expects one parameter");
    const double t = args[0];
    auto interpolate = [&](size_t i) {  // on segment [x_i, x_{i+1}]
        return y[i] + (y[i + 1] - y[i]) * (t - x[i]) / (x[i + 1] - x[i]);
    };
    if (x.size() == 1) return y[0];
    if (t < x.front()) {
        if (leftExtension == 'C') return y.front();
        if (leftExtension == 'L') return interpolate(0);
        throw UserError(
            fmt::format("function {}: {}={} is left of its definition interval [{}, {}] "
                        "(PROL_GAUCHE='EXCLU')",
                        name, parameter_[0], t, x.front(), x.back()));
    }
    if (t > x.back()) {
        if (rightExtension == 'C') return y.back();
        if (rightExtension == 'L') return interpolate(x.size() - 2);
        throw UserError(
            fmt::format("function {}: {}={} is right of its definition interval [{}, {}] "
                        "(PROL_DROITE='EXCLU')",
                        name, parameter_[0], t, x.front(), x.back()));
    }
    size_t i = std::upper_bound(x.begin(), x.end(), t) - x.begin();
    if (i == 0) i = 1;
    if (i >= x.size()) i = x.size() - 1;
    return interpolate(i - 1);
}

}  // namespace ma
