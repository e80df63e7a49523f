#pragma once
// The two header lines code_aster prints above the checks of a TEST_* occurrence (tresu_*: lign1 /
// lign2): "---- <kind>" and the tested object's name in 21 columns, then one 17-column field per
// selector (label above, value below, the value cut to 16 characters).
#include <string>
#include <utility>
#include <vector>

namespace ma {

class TestHeader {
public:
    TestHeader(const std::string& kind, const std::string& name);
    void add(const std::string& label, const std::string& value);
    // Both lines, trailing blanks removed, each after the leading blank of Fortran's list-directed
    // write; trchel prints its label line with format (A), without it (`labelBlank` false).
    std::string text(bool labelBlank = true) const;
    // "RESULTAT=RESU NUME_ORDRE=1 NOM_CHAM=DEPL" for the run summary.
    std::string describe() const;

private:
    std::string labels_, values_;
    std::vector<std::pair<std::string, std::string>> fields_;
};

}  // namespace ma
