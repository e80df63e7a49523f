#include "post/NodalListing.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "core/Error.hpp"
#include "core/FortranFormat.hpp"
#include "post/PythonFormat.hpp"

namespace ma::post {

namespace {

// A Fortran edit descriptor as printf: the scale factor 1P is the form printf gives (d.ddd).
std::string printfOf(const std::string& fortran) {
    const std::string printfFormat = fortranToPrintf(fortran);
    return printfFormat.substr(printfFormat.find('%'));
}

// The width of the text cells of the header (ircnrl's forcmp: A<w> of the real format, A12 else).
int headerWidth(const std::string& fortran) {
    const size_t letter = fortran.find_first_of("DEFGdefg");
    const size_t dot = fortran.find('.');
    if (letter == std::string::npos || dot == std::string::npos || dot <= letter + 1) return 12;
    return std::stoi(fortran.substr(letter + 1, dot - letter - 1));
}

std::string k8(const std::string& name) { return fmt::format("{:<8}", name); }

// 1X, A, then the cells 6 to a line, the following lines indented by 9 (ircnrl's formats).
std::string lineOf(const std::string& first, const std::vector<std::string>& cells) {
    std::string out = " " + first;
    for (size_t i = 0; i < cells.size(); ++i) {
        if (i > 0 && i % 6 == 0) out += "\n         ";
        out += " " + cells[i];
    }
    return out + "\n";
}

struct Extreme {
    double value = 0.0;
    int count = 0;
    std::string node;
};

void track(std::optional<Extreme>& e, double v, const std::string& node, bool isMax) {
    if (!e || (isMax ? v > e->value : v < e->value)) e = Extreme{v, 1, node};
    else if (v == e->value) ++e->count;
}

std::vector<int> selectedComponents(const NodalField& field, const ListingOptions& o) {
    std::vector<int> comps;
    if (o.components.empty()) {
        for (int c = 0; c < field.componentCount(); ++c) comps.push_back(c);
        return comps;
    }
    for (const auto& name : o.components) {
        const int c = field.componentIndex(name);
        if (c < 0)
            throw UserError(fmt::format("NOM_CMP: component {} is not in field {} (components: {})", name, field.name,
                                        fmt::join(field.components, ", ")));
        comps.push_back(c);
    }
    return comps;
}

}  // namespace

std::string nodalFieldTitle(const std::string& fieldName, const ResultStep* step) {
    if (!step) return " CHAMP AUX NOEUDS\n";
    return fmt::format(" CHAMP AUX NOEUDS DE NOM SYMBOLIQUE  {}\n NUMERO D'ORDRE: {} INST: {:12.5E}\n", fieldName,
                       step->order, step->inst);
}

std::string nodalFieldListing(const NodalField& field, const ListingOptions& o) {
    const Mesh& mesh = *field.mesh;
    const auto comps = selectedComponents(field, o);
    const std::string real = printfOf(o.realFormat);
    const int width = headerWidth(o.realFormat);
    auto cell = [&](const std::string& text) { return fmt::format("{:>{}}", k8(text), width); };
    const int dim = mesh.dim;
    std::vector<int> nodes = o.nodes;
    if (nodes.empty())
        for (int n = 0; n < mesh.nodeCount(); ++n) nodes.push_back(n);
    std::vector<std::optional<Extreme>> maxima(field.components.size()), minima(field.components.size());
    std::vector<unsigned char> previous;  // components carried by the previous node
    std::string out;
    for (int n : nodes) {
        std::vector<unsigned char> carried(field.components.size());
        for (size_t c = 0; c < carried.size(); ++c) carried[c] = field.has(n, int(c));
        if (std::none_of(carried.begin(), carried.end(), [](unsigned char x) { return x; })) continue;
        const bool newHeader = carried != previous;
        previous = carried;
        std::vector<int> shown;
        for (int c : comps) {
            if (!carried[size_t(c)]) continue;
            const double v = field.at(n, c);
            if ((o.upper && v > *o.upper) || (o.lower && v < *o.lower)) continue;
            shown.push_back(c);
        }
        if (shown.empty()) continue;
        const std::string& name = mesh.nodeNames[size_t(n)];
        for (int c : shown) {
            if (o.maxima) track(maxima[size_t(c)], field.at(n, c), name, true);
            if (o.minima) track(minima[size_t(c)], field.at(n, c), name, false);
        }
        if (o.maxima || o.minima) continue;
        std::vector<std::string> head, values;
        if (o.coordinates)
            for (int d = 0; d < dim; ++d) {
                head.push_back(cell(std::string(1, char('X' + d))));
                values.push_back(printfReal(real.c_str(), mesh.coords[size_t(n)][size_t(d)]));
            }
        for (int c : shown) {
            head.push_back(cell(field.components[size_t(c)]));
            values.push_back(printfReal(real.c_str(), field.at(n, c)));
        }
        if (newHeader || o.upper || o.lower) out += lineOf("NOEUD   ", head);
        out += lineOf(k8(name), values);
    }
    out += " \n";
    for (const auto& [list, word] : {std::pair{&maxima, "MAXIMALE"}, std::pair{&minima, "MINIMALE"}})
        for (size_t c = 0; c < list->size(); ++c)
            if (const auto& e = (*list)[c])
                out += fmt::format(" LA VALEUR {} DE {} EST {} EN {:4d} NOEUD(S) : {}\n", word, k8(field.components[c]),
                                   printfReal(real.c_str(), e->value), e->count, k8(e->node));
    return out;
}

}  // namespace ma::post
