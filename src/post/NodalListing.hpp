#pragma once
// IMPR_RESU FORMAT='RESULTAT' of nodal fields: code_aster's listing (irecri, titred, ircnrl), one
// line per node with the values of its components, 6 to a line, in FORMAT_R; the header line again
// wherever the set of components a node carries changes; with VALE_MAX / VALE_MIN only the
// extremes of each component and where they are (docs/post.md).
#include <optional>
#include <string>
#include <vector>

#include "fields/Fields.hpp"

namespace ma::post {

struct ListingOptions {
    std::vector<std::string> components;  // NOM_CMP (in this order), empty: every component
    std::vector<int> nodes;               // NOEUD / GROUP_NO / nodes of GROUP_MA, empty: every node
    bool coordinates = false;             // IMPR_COOR='OUI'
    bool maxima = false, minima = false;  // VALE_MAX / VALE_MIN
    std::optional<double> upper, lower;   // BORNE_SUP / BORNE_INF: values beyond are not printed
    std::string realFormat = "1PE21.14";  // FORMAT_R
};

// The subtitle of a field of a result (titred: "CHAMP AUX NOEUDS DE NOM SYMBOLIQUE  DEPL" and
// "NUMERO D'ORDRE: 1 INST:  1.00000E+00"), or of a lone field ("CHAMP AUX NOEUDS").
std::string nodalFieldTitle(const std::string& fieldName, const ResultStep* step);

// The listing of one field (after its title). UserError for a NOM_CMP the field does not have.
std::string nodalFieldListing(const NodalField& field, const ListingOptions& options);

}  // namespace ma::post
