#pragma once
// MED results -> VTK XML files for ParaView (miniaster convert, docs/visualisation.md):
// - OUT.vtu: one file, every step of every field (arrays NAME@NUME_ORDRE when a field has several);
// - OUT.pvd: a time series, one OUT_<NUME_ORDRE>.vtu per step and the collection naming them with
//   their INST (the arrays keep one name over the steps).
// Displacement-like nodal fields (DX, DY[, DZ]) are a 3-component vector (DZ = 0 in 2D), the active
// vectors of the file when the field is DEPL, and their other components (H1X..., LAGS_C) scalar
// arrays NAME_<component> of their own.
#include <string>
#include <vector>

namespace ma::cli {

// Converts every mesh of `input` that carries fields (OUT.vtu/.pvd for the first, OUT_<mesh>.* for
// the others); one summary line per file written. UserError on a bad input or output name.
std::vector<std::string> convertResult(const std::string& input, const std::string& output);

}  // namespace ma::cli
