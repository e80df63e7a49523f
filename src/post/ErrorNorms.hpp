#pragma once
// POST_ERREUR (commands_spec.md §5): error of a computed field against reference formulas,
// integrated on the model's own integration points, one row per GROUP_MA plus TOTAL.
#include <memory>
#include <string>
#include <vector>

#include "post/Table.hpp"

namespace ma {

class Function;
class Model;
class NodalField;
class GaussField;
class MaterialField;

// One reference formula per group (null: the component is zero on that group), per component.
struct ReferenceFormulas {
    std::vector<std::string> components;  // e.g. DX, DY or SIXX..SIYZ
    // formulas[c][g]: component c on group g; an empty vector[c] means the keyword was absent.
    std::vector<std::vector<std::shared_ptr<const Function>>> formulas;
};

// OPTION='DEPL_RELA': L2 norms of u_ref and u_h - u_ref (DX, DY[, DZ]). `material` (CHAM_MATER)
// is needed on crack-tip enriched elements only.
std::shared_ptr<Table> displacementErrorTable(const Model& model, const NodalField& displacement,
                                              const std::vector<std::string>& groups,
                                              const ReferenceFormulas& reference,
                                              const MaterialField* material = nullptr);

// OPTION='ENER_RELA': elastic energies of sigma_ref and sigma_h - sigma_ref with the compliance
// of `material` (DEFORMATION='PETIT'); C_PLAN uses the plane-stress compliance.
std::shared_ptr<Table> energyErrorTable(const Model& model, const GaussField& stress, const MaterialField& material,
                                        const std::vector<std::string>& groups, const ReferenceFormulas& reference);

// Energy density w = 1/2 sigma : S : sigma of isotropic elasticity; sigma = (xx, yy, zz, xy, xz, yz).
// `planeStress` ignores sigma_zz (C_PLAN).
double elasticEnergyDensity(const double sigma[6], double E, double nu, bool planeStress);

}  // namespace ma
