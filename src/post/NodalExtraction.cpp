#include "post/NodalExtraction.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "post/TableOperations.hpp"

namespace ma {
namespace {

const char* const kMomentColumns[6] = {"RESULT_X", "RESULT_Y", "RESULT_Z", "MOMENT_X", "MOMENT_Y", "MOMENT_Z"};
const char* const kForceNames[3] = {"DX", "DY", "DZ"};
const char* const kMomentNames[3] = {"DRX", "DRY", "DRZ"};

// Components requested from one field: all those carried by some node (in the quantity's
// order), or NOM_CMP as given.
std::vector<int> requestedComponents(const NodalField& f, const NodalExtraction& a, const std::string& fieldLabel) {
    std::vector<int> out;
    if (a.allComponents) {
        std::vector<unsigned char> carried(f.components.size(), 0);
        const size_t nc = f.components.size();
        for (size_t i = 0; i < f.present.size(); ++i) carried[i % nc] |= f.present[i];
        for (size_t c = 0; c < nc; ++c)
            if (carried[c]) out.push_back(int(c));
    } else {
        for (const auto& name : a.components) {
            const int c = f.componentIndex(name);
            if (c < 0)
                throw UserError(fmt::format("NOM_CMP: component {} is not in field {} (components: {})", name,
                                            fieldLabel, fmt::join(f.components, ", ")));
            out.push_back(c);
        }
    }
    return out;
}

// NOEUD first, then each GROUP_NO in order; only nodes carrying a requested component, first
// occurrence kept.
std::vector<int> nodeList(const Mesh& mesh, const NodalField& f, const std::vector<int>& comps,
                          const NodalExtraction& a) {
    std::vector<int> candidates;
    for (const auto& n : a.nodes) {
        const int i = mesh.findNode(n);
        if (i < 0) throw UserError(fmt::format("{}/NOEUD: the mesh {} has no node '{}'", a.keywordPath, mesh.name, n));
        candidates.push_back(i);
    }
    for (const auto& g : a.nodeGroups) {
        const auto& members = namedGroup(mesh, GroupKind::Nodes, g, a.keywordPath + "/GROUP_NO");
        candidates.insert(candidates.end(), members.begin(), members.end());
    }
    std::vector<unsigned char> seen(size_t(mesh.nodeCount()), 0);
    std::vector<int> out;
    for (int n : candidates) {
        if (seen[size_t(n)]) continue;
        bool carries = false;
        for (int c : comps) carries = carries || f.has(n, c);
        if (!carries) continue;
        seen[size_t(n)] = 1;
        out.push_back(n);
    }
    return out;
}

size_t textWidth(size_t length, size_t minimum) { return std::max(length, minimum); }

// One field of one action, resolved: the components and nodes it extracts.
struct Block {
    const NodalExtraction* action;
    const NodalField* field;
    const ResultStep* step;
    std::vector<int> comps, nodes;
};

// Every action resolved first: the columns are declared once, from all of them.
struct Extraction {
    std::vector<Block> blocks;
    std::vector<std::string> componentColumns;
    bool anyField = false, anyResult = false;
    bool anyNodeRows = false, anyMoment = false;  // an action extracting node values / with MOMENT
    size_t titleLen = 0, nodeLen = 0, fieldLen = 0, resultLen = 0, nameLen = 0;  // text column widths
};

// The fields an action reads (a CHAM_GD, or NOM_CHAM at each step of a RESULTAT).
std::vector<std::pair<const NodalField*, const ResultStep*>> sourcesOf(const NodalExtraction& a, Extraction& x,
                                                                       std::string& label) {
    std::vector<std::pair<const NodalField*, const ResultStep*>> sources;
    if (a.field) {
        x.anyField = true;
        x.fieldLen = std::max(x.fieldLen, a.field->name.size());
        sources.emplace_back(a.field.get(), nullptr);
        label = a.field->name;
        return sources;
    }
    if (!a.result) throw UserError("POST_RELEVE_T: ACTION needs RESULTAT or CHAM_GD");
    x.anyResult = true;
    x.resultLen = std::max(x.resultLen, a.result->name.size());
    x.nameLen = std::max(x.nameLen, a.fieldName.size());
    for (const ResultStep* s : a.steps) {
        auto f = s->nodal(a.fieldName);
        if (!f)
            throw UserError(fmt::format("NOM_CHAM: result {} has no nodal field {} at NUME_ORDRE {}", a.result->name,
                                        a.fieldName, s->order));
        sources.emplace_back(f.get(), s);
    }
    label = fmt::format("{} {}", a.result->name, a.fieldName);
    return sources;
}

Extraction resolve(const std::vector<NodalExtraction>& actions) {
    Extraction x;
    for (const auto& a : actions) {
        x.titleLen = std::max(x.titleLen, a.title.size());
        std::string label;
        for (auto [f, s] : sourcesOf(a, x, label)) {
            if (!f->mesh) throw UserError(fmt::format("field {} has no mesh", label));
            Block b{&a, f, s, requestedComponents(*f, a, label), {}};
            b.nodes = nodeList(*f->mesh, *f, b.comps, a);
            x.anyNodeRows = x.anyNodeRows || !a.resultant;
            x.anyMoment = x.anyMoment || a.moment;
            if (!a.resultant)
                for (int n : b.nodes) x.nodeLen = std::max(x.nodeLen, f->mesh->nodeNames[size_t(n)].size());
            if (!a.moment)
                for (int c : b.comps)
                    if (std::find(x.componentColumns.begin(), x.componentColumns.end(), f->components[size_t(c)]) ==
                        x.componentColumns.end())
                        x.componentColumns.push_back(f->components[size_t(c)]);
            x.blocks.push_back(std::move(b));
        }
    }
    return x;
}

void declareColumns(const Extraction& x, Table& table) {
    table.addColumn("INTITULE", textColumnFor(textWidth(x.titleLen, 16)));
    if (x.anyNodeRows) table.addColumn("NOEUD", textColumnFor(textWidth(x.nodeLen, 8)));
    if (x.anyField) table.addColumn("CHAM_GD", textColumnFor(textWidth(x.fieldLen, 8)));
    if (x.anyResult) {
        table.addColumn("RESU", textColumnFor(textWidth(x.resultLen, 8)));
        table.addColumn("NOM_CHAM", textColumnFor(textWidth(x.nameLen, 16)));
        table.addColumn("NUME_ORDRE", ColumnType::integer());
        table.addColumn("INST", ColumnType::real());  // evol_elas / evol_noli results
    }
    if (x.anyNodeRows)
        for (const char* c : {"ABSC_CURV", "COOR_X", "COOR_Y", "COOR_Z"}) table.addColumn(c, ColumnType::real());
    for (const auto& c : x.componentColumns) table.addColumn(c, ColumnType::real());
    if (x.anyMoment)
        for (const char* c : kMomentColumns) table.addColumn(c, ColumnType::real());
}

// A new row with the action's title and where its values come from (result and order, or field).
size_t startRow(const Block& b, Table& table) {
    const size_t r = table.addRow();
    table.set(r, 0, b.action->title);
    if (b.step) {
        table.set(r, size_t(table.columnIndex("RESU")), b.action->result->name);
        table.set(r, size_t(table.columnIndex("NOM_CHAM")), b.action->fieldName);
        table.set(r, size_t(table.columnIndex("NUME_ORDRE")), static_cast<long long>(b.step->order));
        table.set(r, size_t(table.columnIndex("INST")), b.step->inst);
    } else {
        table.set(r, size_t(table.columnIndex("CHAM_GD")), b.field->name);
    }
    return r;
}

// RESULTANTE: the sum over the block's nodes of each component; with MOMENT the force (DX, DY, DZ
// among the RESULTANTE components) and its moment about POINT, sum of (x - POINT) x F plus the
// nodal moments DRX, DRY, DRZ where the field has them.
void addResultantRow(const Block& b, Table& table) {
    const size_t r = startRow(b, table);
    const NodalField& f = *b.field;
    if (!b.action->moment) {
        for (int c : b.comps) {
            double sum = 0.0;
            for (int n : b.nodes)
                if (f.has(n, c)) sum += f.at(n, c);
            table.set(r, size_t(table.columnIndex(f.components[size_t(c)])), sum);
        }
        return;
    }
    auto valueOf = [&](int n, const char* name) {
        const int c = f.componentIndex(name);
        return c >= 0 && f.has(n, c) ? f.at(n, c) : 0.0;
    };
    auto requested = [&](const char* name) {
        return std::find(b.action->components.begin(), b.action->components.end(), name) != b.action->components.end();
    };
    std::array<double, 6> sum{};
    const auto& p = b.action->point;
    for (int n : b.nodes) {
        std::array<double, 3> force{}, arm{};
        for (int d = 0; d < 3; ++d) {
            force[size_t(d)] = requested(kForceNames[d]) ? valueOf(n, kForceNames[d]) : 0.0;
            arm[size_t(d)] = f.mesh->coords[size_t(n)][size_t(d)] - p[size_t(d)];
            sum[size_t(d)] += force[size_t(d)];
            sum[size_t(3 + d)] += valueOf(n, kMomentNames[d]);
        }
        sum[3] += arm[1] * force[2] - arm[2] * force[1];
        sum[4] += arm[2] * force[0] - arm[0] * force[2];
        sum[5] += arm[0] * force[1] - arm[1] * force[0];
    }
    for (size_t k = 0; k < 6; ++k) table.set(r, size_t(table.columnIndex(kMomentColumns[k])), sum[k]);
}

// One row per node of the block, with its curvilinear abscissa along the node list.
void addNodeRows(const Block& b, Table& table) {
    const size_t colNode = size_t(table.columnIndex("NOEUD"));
    const size_t colAbsc = size_t(table.columnIndex("ABSC_CURV"));
    const Mesh& mesh = *b.field->mesh;
    std::vector<size_t> compCol;
    for (int c : b.comps) compCol.push_back(size_t(table.columnIndex(b.field->components[size_t(c)])));
    double absc = 0.0;
    for (size_t k = 0; k < b.nodes.size(); ++k) {
        const int n = b.nodes[k];
        const auto& x = mesh.coords[size_t(n)];
        if (k > 0) {
            const auto& p = mesh.coords[size_t(b.nodes[k - 1])];
            absc += std::sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) +
                              (x[2] - p[2]) * (x[2] - p[2]));
        }
        const size_t r = startRow(b, table);
        table.set(r, colNode, mesh.nodeNames[size_t(n)]);
        table.set(r, colAbsc, absc);
        for (int d = 0; d < 3; ++d) table.set(r, colAbsc + 1 + size_t(d), x[size_t(d)]);
        for (size_t j = 0; j < b.comps.size(); ++j)
            if (b.field->has(n, b.comps[j])) table.set(r, compCol[j], b.field->at(n, b.comps[j]));
    }
}

}  // namespace

std::shared_ptr<Table> extractNodalValues(const std::vector<NodalExtraction>& actions) {
    auto table = std::make_shared<Table>();
    const Extraction x = resolve(actions);
    declareColumns(x, *table);
    for (const Block& b : x.blocks) {
        if (b.action->resultant) addResultantRow(b, *table);
        else addNodeRows(b, *table);
    }
    return table;
}

}  // namespace ma
