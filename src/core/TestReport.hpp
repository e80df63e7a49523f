#pragma once
// Accounting of the TEST_* checks of a run (TEST_TABLE, TEST_RESU...). Each printed check line
// (OK / NOOK / SKIP) is also recorded here; the supervisor prints a summary at the end of the run,
// derives the diagnostic (NOOK_TEST_RESU...) and the exit status (2 when any check is NOOK).
#include <string>
#include <vector>

namespace ma {

struct TestLine {
    enum class Status { Ok, Nook, Skip };
    // "NON_REGRESSION" for a check against VALE_CALC, otherwise the REFERENCE type of the check
    // ("ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER", "NON_DEFINI").
    std::string kind;
    Status status = Status::Ok;
    // What was tested, for the list of failures: e.g. "TEST_TABLE DEPZON_1 DX MIN: computed
    // -0.25, expected -0.2501, error 0.04% > 1e-11%" (command, .comm line are added by the caller).
    std::string description;

    bool isNonRegression() const { return kind == "NON_REGRESSION"; }
};

class TestReport {
public:
    void add(TestLine line) { lines_.push_back(std::move(line)); }
    const std::vector<TestLine>& lines() const { return lines_; }

    // Counts over the reference checks (isNonRegression() == false) or the non-regression ones.
    int count(TestLine::Status status, bool nonRegression) const;
    int nookCount() const;
    bool empty() const { return lines_.empty(); }

    // Summary for the end of the message log: counts per category and the list of NOOK lines.
    std::string summary() const;
    void reset() { lines_.clear(); }

private:
    std::vector<TestLine> lines_;
};

// The report of the current run.
TestReport& testReport();

}  // namespace ma
