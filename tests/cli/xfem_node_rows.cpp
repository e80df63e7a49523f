// The interfaces of ssnv511 placed relative to the node rows in every way (docs/xfem.md, "Interfaces
// on node rows"): one interface along a row of nodes and the other through cells, both along rows,
// both through cells, at N = 2, 4, 5, 6 cells per side. code_aster's ssnv511a-d, unmodified, on these
// meshes must give the exact piecewise rigid motion: every ANALYTIQUE check OK and a relative L2
// error of round-off. At N = 4 with the branches through the column of cells next to the prescribed
// sides, the nodes of those sides on the main interface lie in cells that see the three interfaces:
// their DDL_IMPO used to be imposed as if they were not enriched (DEPZON_1 DX MIN -0.3117 for -0.25).
// At N = 2 the prescribed nodes themselves carry the three interfaces (one relation per side).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "parser_run.hpp"

using namespace ma::test;

namespace {

struct Placement {
    const char* type;
    char modelisation;  // ssnv511<modelisation>.comm
    int n;
    double offsetX, offsetY;
    int referenceChecks;
};

std::string name(const Placement& p) {
    return fmt::format("{}_N{}_offset_{}_{}", p.type, p.n, p.offsetX == 0 ? "0" : "half",
                       p.offsetY == 0 ? "0" : "half");
}

// Relative error of POST_ERREUR's L2 table (TOTAL line of "ERREUR EN NORME L2") in the .resu.
double relativeL2(const std::string& resu) {
    const auto at = resu.find("ERREUR EN NORME L2");
    if (at == std::string::npos) return 1.0;
    std::smatch m;
    const std::string rest = resu.substr(at);
    if (!std::regex_search(rest, m, std::regex(R"(\nTOTAL\s+\S+\s+\S+\s+(\S+))"))) return 1.0;
    return std::stod(m[1]);
}

int count(const std::string& text, const std::string& what) {
    int c = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++c;
    return c;
}

void PrintTo(const Placement& p, std::ostream* os) { *os << name(p); }

class NodeRows : public ::testing::TestWithParam<Placement> {};

TEST_P(NodeRows, Ssnv511IsExact) {
    const Placement p = GetParam();
    const auto dir = freshDir();
    const auto tool = std::filesystem::path(MINIASTER_BINARY).parent_path() / "tools" / "ssnv511_mesh";
    const auto mesh = dir / "m.med";
    const auto make =
        fmt::format("'{}' --type {} --n {} --offset {} {}{} -o '{}' > /dev/null 2>&1", tool.string(), p.type, p.n,
                    p.offsetX, p.offsetY, std::string(p.type) == "tetra4" ? " --zbounds 0 1" : "", mesh.string());
    ASSERT_EQ(std::system(make.c_str()), 0) << make;
    const auto comm = fmt::format("{}/astest/ssnv511{}.comm", MINIASTER_SHARED_DIR, p.modelisation);
    const auto r = runMiniaster(dir, comm, fmt::format("--mesh '{}'", mesh.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file(fmt::format("out/ssnv511{}.resu", p.modelisation));
    EXPECT_EQ(count(resu, "\n OK   ANALYTIQUE"), p.referenceChecks) << resu;
    EXPECT_EQ(count(resu, "\nNOOK"), 0) << resu;
    EXPECT_LE(relativeL2(resu), 1e-12) << resu;
}

std::vector<Placement> placements() {
    std::vector<Placement> out;
    const std::pair<const char*, char> types[] = {{"quad4", 'a'}, {"tria3", 'b'}, {"hexa8", 'c'}, {"tetra4", 'd'}};
    for (const auto& [type, modelisation] : types)
        for (int n : {2, 4, 5, 6})
            for (const auto& [ox, oy] : {std::pair{0.5, 0.0}, {0.0, 0.5}, {0.5, 0.5}, {0.0, 0.0}})
                out.push_back({type, modelisation, n, ox, oy, modelisation <= 'b' ? 18 : 26});
    return out;
}

INSTANTIATE_TEST_SUITE_P(Ssnv511, NodeRows, ::testing::ValuesIn(placements()),
                         [](const ::testing::TestParamInfo<Placement>& placement) { return name(placement.param); });

}  // namespace
