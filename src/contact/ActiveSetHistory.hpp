#pragma once
// The contact statuses of every iteration of one increment's contact loop (ContactLoop): how many
// points each update activated and released, how often each point changed, and whether the new
// active set repeats an earlier one. The loop is deterministic (same statuses, same linear system),
// so a repeated active set is a cycle that more iterations cannot leave: the loop stops there and the
// error names the points that keep changing, where they are and their gap and contact function
// (docs/contact.md, "Robustness of the contact loop").
#include <string>
#include <vector>

namespace ma::contact {

class ContactTerms;

class ActiveSetHistory {
public:
    explicit ActiveSetHistory(std::vector<char> initial);

    struct Step {
        int activated = 0;
        int released = 0;
        int repeats = -1;  // contact iteration whose statuses these repeat (0: the initial ones), -1: none
    };
    // Records the statuses after the next update.
    Step record(const std::vector<char>& statuses);

    // How many updates changed point p's status.
    int changes(int p) const { return changes_[size_t(p)]; }

    // A heading, then one line per point that changed status more than once (or, if none did, at the
    // last update), most changes first, at most `limit` lines plus a count of the others: the interface, the
    // point's coordinates, the parent cell(s) of its facet, the changes, and at the state u its
    // current status, gap, contact function and the block fractions of the facet's two sides.
    std::string flippingPoints(const ContactTerms& terms, const std::vector<double>& u, int limit) const;

private:
    std::vector<std::vector<char>> sets_;  // sets_[k]: the statuses after iteration k (0: initial)
    std::vector<int> changes_;
    std::vector<char> changedLast_;
};

}  // namespace ma::contact
