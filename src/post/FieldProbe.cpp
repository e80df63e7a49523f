#include "post/FieldProbe.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace ma {
namespace {

// Index of `component` in the field's components; UserError listing them (code_aster CALCULEL6_91,
// CHAMPS_3).
int componentOf(const std::vector<std::string>& components, const std::string& component, const std::string& quantity,
                const std::string& where) {
    const auto it = std::find(components.begin(), components.end(), component);
    if (it == components.end())
        throw UserError(fmt::format("{}: the field ({}) has no component {} (components: {})", where, quantity,
                                    component, fmt::join(components, ", ")));
    return static_cast<int>(it - components.begin());
}

// Accumulates values the way tresu_champ_all / tresu_champ_cmp do (MIN / MAX from the first value).
class Accumulator {
public:
    explicit Accumulator(Reduction r) : reduction_(r) {}
    void add(double v) {
        switch (reduction_) {
            case Reduction::Sum: value_ += v; break;
            case Reduction::SumAbs: value_ += std::abs(v); break;
            case Reduction::Min: value_ = count_ == 0 ? v : std::min(value_, v); break;
            case Reduction::Max: value_ = count_ == 0 ? v : std::max(value_, v); break;
            case Reduction::None: break;
        }
        ++count_;
    }
    double result(const std::string& where) const {
        if (reduction_ == Reduction::None) throw UserError(where + ": TYPE_TEST is needed to reduce a field");
        if (count_ == 0 && (reduction_ == Reduction::Min || reduction_ == Reduction::Max))
            throw UserError(where + ": the field holds no value to take the extremum of");
        return value_;
    }

private:
    Reduction reduction_;
    double value_ = 0.0;
    size_t count_ = 0;
};

}  // namespace

double nodalValue(const NodalField& field, int node, const std::string& component, const std::string& where) {
    const int c = componentOf(field.components, component, field.quantity, where);
    if (!field.has(node, c))
        throw UserError(fmt::format("{}: node {} does not carry component {} in this field (code_aster CALCULEL6_93)",
                                    where, field.mesh->nodeNames[node], component));
    return field.at(node, c);
}

double gaussValue(const GaussField& field, int cell, int point, const std::string& component,
                  const std::string& where) {
    const int c = componentOf(field.components, component, field.quantity, where);
    const auto element = std::find(field.cells.begin(), field.cells.end(), cell);
    if (element == field.cells.end())
        throw UserError(fmt::format("{}: the field has no value on cell {}", where, field.mesh->cellNames[cell]));
    const size_t e = static_cast<size_t>(element - field.cells.begin());
    const int points = field.pointOffsets[e + 1] - field.pointOffsets[e];
    if (point < 1 || point > points)
        throw UserError(fmt::format("{}: cell {} has {} integration points in this field, POINT={} is not one of them",
                                    where, field.mesh->cellNames[cell], points, point));
    return field.values[size_t(field.pointOffsets[e] + point - 1) * field.components.size() + size_t(c)];
}

double reduceField(const NodalField& field, Reduction reduction, const std::optional<std::string>& component,
                   const std::string& where) {
    Accumulator acc(reduction);
    const int count = field.componentCount();
    const int only = component ? componentOf(field.components, *component, field.quantity, where) : -1;
    const int nodes = count == 0 ? 0 : static_cast<int>(field.values.size()) / count;
    for (int n = 0; n < nodes; ++n)
        for (int c = 0; c < count; ++c)
            if ((only < 0 || c == only) && field.has(n, c)) acc.add(field.at(n, c));
    return acc.result(where);
}

double reduceField(const GaussField& field, Reduction reduction, const std::optional<std::string>& component,
                   const std::string& where) {
    Accumulator acc(reduction);
    const size_t count = field.components.size();
    const int only = component ? componentOf(field.components, *component, field.quantity, where) : -1;
    for (size_t i = 0; i < field.values.size(); ++i)
        if (only < 0 || int(i % count) == only) acc.add(field.values[i]);
    return acc.result(where);
}

}  // namespace ma
