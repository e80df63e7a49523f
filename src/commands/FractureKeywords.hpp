#pragma once
// What CALC_G and POST_K1_K2_K3 share: the orders chosen (TOUT_ORDRE, NUME_ORDRE, INST with
// CRITERE/PRECISION) and the checks of the crack against the result.
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "fe/Result.hpp"
#include "parser/KeywordTree.hpp"
#include "xfem/Crack.hpp"

namespace ma {

std::vector<const ResultStep*> fractureSteps(const Result& result, const KeywordSet& kw);

// The crack must be one of the result's model's and have a front (2D tips and 3D fronts); for the
// theta method (`thetaMethod`) the result be without volume forces, and its lip pressures on this
// crack only (the terms miniaster computes).
void checkCrackResult(const Result& result, const xfem::Crack& crack, const std::string& keyword,
                      const std::string& command, bool thetaMethod);

// CALC_G on a 3D crack's front (CalcG3D.cpp).
ConceptPtr calcG3D(const KeywordSet& kw, const Result& result, const xfem::Crack& crack);

}  // namespace ma
