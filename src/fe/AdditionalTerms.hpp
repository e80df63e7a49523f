#pragma once
// Terms another engine adds to a mechanical problem (contact: multipliers and their couplings).
// All indices are dofs of the problem's numbering(); the extra unknowns themselves come from
// ExtraUnknowns (fe/DofNumbering.hpp).
#include <functional>
#include <utility>
#include <vector>

namespace ma {

class AdditionalTerms {
public:
    virtual ~AdditionalTerms() = default;
    // Dof pairs (i, j) that may carry matrix entries besides the element couplings (the pattern
    // is made symmetric). Asked when the pattern is built.
    virtual void couplings(std::vector<std::pair<int, int>>& pairs) const = 0;
    // Tangent contributions at state u: add(i, j, value) (both triangles explicitly).
    virtual void tangent(const std::vector<double>& u, const std::function<void(int, int, double)>& add) const = 0;
    // Contribution to the residual R = F_int - F_ext + ... at state u.
    virtual void residual(const std::vector<double>& u, std::vector<double>& R) const = 0;
    // Unknowns of the engine itself (e.g. contact multipliers at integration points), numbered
    // after the dofs of numbering(): u and R then have numbering().size() + extraUnknowns()
    // entries. Their rows are left out of the convergence check (as code_aster skips contact
    // rows) and the matrix is treated as symmetric indefinite.
    virtual int extraUnknowns() const { return 0; }
};

}  // namespace ma
