#pragma once
// The alarms of CALC_G and POST_K1_K2_K3 (docs/messages.md, docs/cracks.md).
#include "core/Message.hpp"

namespace ma {

// The number of cell sizes, the smallest and the largest tip cell size of the crack's fronts.
inline constexpr Message<int, double, double> RUPTURE0_17{
    "RUPTURE0_17",
    "the cells at the {} front points of the crack differ in size by more than a factor 2 ({:.6e} to {:.6e}): the "
    "default ABSC_CURV_MAXI (5 times the largest) reaches many cells behind the fronts with the smallest cells. "
    "Give ABSC_CURV_MAXI, or mesh the fronts' neighbourhood evenly."};

// The smallest and the largest TAILLE_R along the front of CALC_G without R_INF / R_SUP.
inline constexpr Message<double, double> RUPTURE1_16{
    "RUPTURE1_16",
    "the cells at the front's points differ in size by more than a factor 2 ({:.6e} to {:.6e}): the default crown "
    "R_INF, R_SUP (2 and 4 times the largest) reaches many cells around the points with the smallest cells. Give "
    "R_INF and R_SUP, or mesh the front's neighbourhood evenly."};

inline constexpr MessageText fractureMessages[] = {
    entry(RUPTURE0_17),
    entry(RUPTURE1_16),
};

}  // namespace ma
