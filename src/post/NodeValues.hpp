#pragma once
// CALC_CHAMP's fields derived from a field at integration points (SIEF_ELGA ...): the same field on
// a subset of cells (SIGM_ELGA), its values at the cells' nodes (ELNO) and their average at the
// mesh nodes (NOEU), X-FEM sub-cells handled as code_aster's te0289 does (docs/post.md).
#include <memory>
#include <vector>

#include "fe/Enrichment.hpp"
#include "fields/Fields.hpp"

namespace ma::post {

// The elements of `field` whose cell is kept (keepCell[cell] != 0), points and values copied.
std::shared_ptr<GaussField> restrictToCells(const GaussField& field, const std::vector<char>& keepCell);

// ELNO: per element, the values at its cell's nodes. A classical element fits its points by least
// squares in the shape functions of its vertex element (exact extrapolation when the points are as
// many, the mean when fewer); an X-FEM element (`enrichment` says which) fits each sub-cell
// linearly and gives a parent node the mean of the sub-cells having it as a vertex.
std::shared_ptr<GaussField> nodeValues(const GaussField& field, const Enrichment* enrichment);

// NOEU: at each node, the mean of the ELNO values of the elements around it; nodes of no element
// carry no component.
std::shared_ptr<NodalField> nodalAverage(const GaussField& elno);

}  // namespace ma::post
