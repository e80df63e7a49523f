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
    out += fmt::format("  non-regression checks       {:6d}   {:6d} {:6d}\n", count(S::Ok, true),
                       count(S::Nook, true), count(S::Skip, true));
    if (nookCount() > 0) {
        out += "  NOOK checks:\n";
        for (const auto& l : lines_)
            if (l.status == S::Nook) out += fmt::format("    NOOK {:<16} {}\n", l.kind, l.description);
    }
    return out;
}

}  // namespace ma
