#include "core/TestReport.hpp"

#include <fmt/format.h>

namespace ma {

TestReport& testReport() {
    static TestReport report;
    return report;
}

int TestReport::count(TestLine::Status status, bool nonRegression) const {
    int n = 0;
    for (const auto& l : lines_)
        if (l.status == status && l.isNonRegression() == nonRegression) ++n;
    return n;
}

int TestReport::nookCount() const {
    int n = 0;
    for (const auto& l : lines_)
        if (l.status == TestLine::Status::Nook) ++n;
    return n;
}

std::string TestReport::summary() const {
    using S = TestLine::Status;
    std::string out = "  TEST SUMMARY                     OK     NOOK   SKIP\n";
    out += fmt::format("  reference checks            {:6d}   {:6d} {:6d}\n", count(S::Ok, false),
                       count(S::Nook, false), count(S::Skip, false));
    out += fmt::format("  non-regression checks       {:6d}   {:6d} {:6d}\n", count(S::Ok, true), count(S::Nook, true),
                       count(S::Skip, true));
    // The verdict in words: NON_REGRESSION values are code_aster's own results, not references
    // (ssnv511e-h carry its inexact contact values, README "Running code_aster's originals").
    const int references = count(S::Ok, false) + count(S::Nook, false);
    const int differing = count(S::Nook, true);
    if (count(S::Nook, false) > 0)
        out += fmt::format("  {} of {} reference checks NOOK", count(S::Nook, false), references);
    else if (references == 0) out += "  no reference check";
    else out += fmt::format("  all {} reference checks OK", references);
    out += differing > 0 ? fmt::format("; {} non-regression value{} differ{} from code_aster's own\n", differing,
                                       differing > 1 ? "s" : "", differing > 1 ? "" : "s")
                         : "\n";
    if (nookCount() > 0) {
        out += "  NOOK checks:\n";
        for (const auto& l : lines_)
            if (l.status == S::Nook) out += fmt::format("    NOOK {:<16} {}\n", l.kind, l.description);
    }
    return out;
}

}  // namespace ma
