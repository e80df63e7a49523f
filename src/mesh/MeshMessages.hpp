#pragma once
// The meshes' alarms: LIRE_MAILLAGE (its readers and checks) and DEFI_GROUP (docs/messages.md).
#include <cstddef>
#include <string>

#include "core/Message.hpp"

namespace ma {

// FORMAT='ASTER' (.mail): the file, the line, then the group.
inline constexpr Message<std::string, int, std::string, std::string> MODELISA4_97{
    "MODELISA4_97", "mesh {}, line {}: group name '{}' is cut to 24 characters: '{}'"};
inline constexpr Message<std::string, int, std::string, std::string> MODELISA5_6{
    "MODELISA5_6", "mesh {}, line {}: '{}' is repeated in GROUP_NO '{}'; the repeat is dropped"};
inline constexpr Message<std::string, int, std::string, std::string> MODELISA5_8{
    "MODELISA5_8", "mesh {}, line {}: '{}' is repeated in GROUP_MA '{}'; the repeat is dropped"};
// The block keyword (GROUP_NO or GROUP_MA) and the group.
inline constexpr Message<std::string, int, std::string, std::string> MODELISA4_80{
    "MODELISA4_80", "mesh {}, line {}: {} '{}' is empty and is not created"};

// VERI_MAIL: the file, the count, the first one.
inline constexpr Message<std::string, long, std::string> MODELISA_VERI_MAIL_ORPHAN_NODES{
    "MODELISA_VERI_MAIL", "mesh {}: {} nodes belong to no cell (first one: {})"};
// VERI_MAIL: the file, the count, the first pairs / cells.
inline constexpr Message<std::string, size_t, std::string> MODELISA8_13{
    "MODELISA8_13",
    "mesh {}: {} pair(s) of cells have the same nodes (double cells): {}; the domain is counted twice there (a "
    "heavier, stiffer model), and a cell replaced by a copy of its neighbour leaves a hole"};
// VERI_MAIL/VERIF='NON': the file.
inline constexpr Message<std::string> MODELISA5_49{
    "MODELISA5_49",
    "mesh {}: VERI_MAIL/VERIF='NON': nodes of no cell, cells with a repeated node, double cells and flat cells are "
    "not looked for (the coordinates and the cells' Jacobians still are)"};
// VERI_MAIL: the file, the count, APLAT, the first cells with their ratio.
inline constexpr Message<std::string, size_t, double, std::string> MODELISA8_15{
    "MODELISA8_15",
    "mesh {}: {} cell(s) have nearly coincident nodes, their shortest distance between two nodes below APLAT = {} "
    "times their longest: {}"};

// FORMAT='MED' without NOM_MED: the count, the mesh read.
inline constexpr Message<size_t, std::string> MED_MULTI{
    "MED_MULTI", "the MED file holds {} meshes; the first one, '{}', is read (use NOM_MED to choose)"};

// The mesh, the count, "left-handed" (3D) or "clockwise" (2D), the counts per cell type.
inline constexpr Message<std::string, int, std::string, std::string> MAILLAGE_ORIENTATION{
    "MAILLAGE_ORIENTATION",
    "mesh {}: {} cells are {} in code_aster's node order (negative Jacobian): {}; they are integrated with "
    "|det J|, as code_aster does, and give the same elements as cells numbered the other way"};
// The mesh, the count, the first cells.
inline constexpr Message<std::string, size_t, std::string> MAILLAGE1_1{
    "MAILLAGE1_1",
    "mesh {}: {} cell(s) are too distorted, their Jacobian changes sign among the integration points: {}; is the "
    "connectivity in code_aster's order?"};
// The mesh, the faces, the dimension, the cells owning them and the first ones.
inline constexpr Message<std::string, int, int, size_t, std::string> MAILLAGE_NON_CONFORME{
    "MAILLAGE_NON_CONFORME",
    "mesh {}: not conforming: {} faces of its {}D cells belong to one cell only yet lie inside the domain, "
    "overlapping another such face ({} cells: {}); a face between two cells is cut differently on its two sides "
    "(a quadrangle split along different diagonals, or a hanging node). The displacement is discontinuous across "
    "them: no element reproduces even a uniform stress on this mesh"};

// DEFI_GROUP ALARME='OUI': the keyword, "cell" or "node", the group.
inline constexpr Message<std::string, std::string, std::string> SOUSTRUC_36{
    "SOUSTRUC_36", "{}: the {} group '{}' would be empty; it is not created"};
inline constexpr Message<std::string> SOUSTRUC_37{"SOUSTRUC_37", "node group '{}' already exists: it is kept as it is"};
inline constexpr Message<std::string, std::string, std::string> SOUSTRUC_38{"SOUSTRUC_38",
                                                                            "{}: there is no {} group '{}' to destroy"};

// DEFI_GROUP: a node group standing for one node (GROUP_NO_CENTRE; GROUP_NO_ORIG / GROUP_NO_EXTR) holds
// several: the keyword, the group, its size, the node used.
inline constexpr Message<std::string, std::string, size_t, std::string> MODELISA9_29{
    "MODELISA9_29", "{}: the node group '{}' has {} nodes; its first node {} is the centre"};
inline constexpr Message<std::string, std::string, size_t, std::string> SOUSTRUC_87{
    "SOUSTRUC_87", "{}: the node group '{}' has {} nodes; its first node {} is the end of the line"};

inline constexpr MessageText meshMessages[] = {
    entry(MODELISA4_97),
    entry(MODELISA5_6),
    entry(MODELISA5_8),
    entry(MODELISA4_80),
    entry(MODELISA_VERI_MAIL_ORPHAN_NODES),
    entry(MODELISA5_49),
    entry(MODELISA8_13),
    entry(MODELISA8_15),
    entry(MED_MULTI),
    entry(MAILLAGE_ORIENTATION),
    entry(MAILLAGE1_1),
    entry(MAILLAGE_NON_CONFORME),
    entry(SOUSTRUC_36),
    entry(SOUSTRUC_37),
    entry(SOUSTRUC_38),
    entry(MODELISA9_29),
    entry(SOUSTRUC_87),
};

}  // namespace ma
