# Validation runs: whole .comm files executed by the miniaster binary.
#
# 1. Every project case astest/<case>.export is a test. It must end with exit status 0, unless its
#    .export declares `P expected_diag NOOK_TEST_RESU` (exit 2 expected) — code_aster's own
#    convention for cases that are meant to fail a TEST.
# 2. The originals in ../shared/astest that miniaster supports are listed explicitly below.
set(_run ${CMAKE_SOURCE_DIR}/tools/run_validation.sh)
file(GLOB _cases CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/astest/*.export)
# The 3D crack cases that take 15-40 s each run on one process only (the CI's 25 minutes): two
# processes are checked on the 3D crack tip by xfem_tip_williams_hexa8/_tetra4 and xfem_tip_k3d_hexa8
# (POST_K1_K2_K3), on CALC_G with the lip term by glip_griffith_pressure.
set(_one_process_only glip_ssnv185c_linear xfem_penny_hexa8)
# Cases on ssnv185c's mesh whose solves and CALC_G / POST_K1_K2_K3 calls original.ssnv185c runs too:
# kept for `./miniaster run` (their extra checks: K2, K3 = 0 and G_IRWIN on every crown; K1 at every
# front point, the lip pressure's superposition, DX = 0 of POST_CHAM_XFEM), not in ctest (30-40 s each
# against the CI's 25 minutes).
set(_not_in_ctest g3d_ssnv185c_faces xfem_crack_185c_scene)
foreach(_export ${_cases})
  get_filename_component(_name ${_export} NAME_WE)
  if(_name IN_LIST _not_in_ctest)
    continue()
  endif()
  add_test(NAME astest.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${_export} ${CMAKE_BINARY_DIR}/astest-out/${_name})
  if(_name IN_LIST _one_process_only)
    continue()
  endif()
  # The same case on two MPI processes (docs/mpi.md): the same TEST results as the run above.
  set_tests_properties(astest.${_name} PROPERTIES FIXTURES_SETUP one_process.${_name})
  add_test(NAME astest_np2.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${_export} ${CMAKE_BINARY_DIR}/astest-out/np2_${_name}
                   --same-tests-as ${CMAKE_BINARY_DIR}/astest-out/${_name} -- --np 2)
  set_tests_properties(astest_np2.${_name} PROPERTIES FIXTURES_REQUIRED one_process.${_name} PROCESSORS 2)
endforeach()

# Originals (read in place from ../shared/astest, never copied). Added as their issues land.
set(MINIASTER_ORIGINALS ssnv511a ssnv511b ssnv511c ssnv511d ssnv511e ssnv511f ssnv511g ssnv511h CACHE INTERNAL "")
# code_aster's junction family (docs/family.md).
set(MINIASTER_FAMILY ssnv512a ssnv512c ssnv512e ssnv512f ssnv513a ssnv513b ssnv513c ssnv513d ssnv513e ssnv513g
    ssnv513h CACHE INTERNAL "")
# Beyond the family: code_aster's other interface tests as their features land (docs/commands.md).
set(MINIASTER_BEYOND ssnv173b ssnv173d ssnv173e ssnv173f ssnv173g ssnv195a ssnv201a ssnv245a ssnv203a ssnv191b
    ssnp169a CACHE INTERNAL "")
# Cracks (issue 26, docs/cracks.md): step 1, the level sets of a FORM_FISS crack; step 2 in 3D
# (ssnv198a: TOPOLOGIQUE, K1 = K2 = K3 = 0, FACE_IMPO DNOR on Heaviside nodes); step 3 in 2D
# (ssnp138a: CALC_G and POST_K1_K2_K3 on an inclined crack at five angles) and in 3D (ssnv185c: CALC_G
# on six crowns, POST_K1_K2_K3, POST_CHAM_XFEM on a 3D front, within its .export's 512 MB: 480 MB,
# docs/cracks.md "ssnv185c"; its time_limit 120 also bounds the elapsed time: ~75 s on a quiet machine).
set(MINIASTER_CRACKS sslv318a ssnv198a ssnp138a ssnv185c CACHE INTERNAL "")
# Originals whose NON_REGRESSION values are code_aster's own inexact results (docs/contact.md,
# docs/family.md): exit 2 accepted when every reference check is OK (tools/run_validation.sh).
set(MINIASTER_ORIGINALS_INEXACT_VALE_CALC ssnv511e ssnv511f ssnv511g ssnv511h ssnv512f ssnv513e ssnv513g
    ssnp169a ssnp138a ssnv185c CACHE INTERNAL "")
# The one reference check allowed to stay NOOK: ssnv513e's ANALYTIQUE envelope -(X+5)/100 +- 0.06 of
# DEPZON_4 DX-DX MAX, which the converged solution itself exceeds (0.0629 at N = 81, the refinement
# study of docs/family.md). Its DEPZON_1 DX-DX MAX line is OK (0.044) and is not excused.
set(_ssnv513e_allowed --allow-reference-nook "TEST_TABLE (ssnv513e.comm line 332) DEPZON_4 DX-DX MAX")
# ssnp138a's POST_K1_K2_K3 K1 at 60 degrees, tip 2 (+2.12 % against 2 %; tip 1 is OK against its 3 %):
# the file's grid gives that to both tips (the discrete problem is symmetric under the half-turn); the
# refined solution is +1.2 to +1.3 %, inside both tolerances, and code_aster's +2.79 / +1.76 % are an
# asymmetric discretisation (docs/cracks.md, docs/study/ssnp138a_refinement.md). Every other check is OK.
set(_ssnp138a_allowed --allow-reference-nook "TEST_TABLE (ssnp138a.comm line 346) PK2_4 K1")
foreach(_name ${MINIASTER_ORIGINALS} ${MINIASTER_FAMILY} ${MINIASTER_BEYOND} ${MINIASTER_CRACKS})
  set(_opt "")
  if(_name IN_LIST MINIASTER_ORIGINALS_INEXACT_VALE_CALC)
    set(_opt --allow-nonregression-nook)
  endif()
  if(_name STREQUAL "ssnv513e")
    list(APPEND _opt ${_ssnv513e_allowed})
  endif()
  if(_name STREQUAL "ssnp138a")
    list(APPEND _opt ${_ssnp138a_allowed})
  endif()
  add_test(NAME original.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${CMAKE_SOURCE_DIR}/../shared/astest/${_name}.export
                   ${CMAKE_BINARY_DIR}/astest-out/${_name} ${_opt})
  # Label ssnv511: the originals `./miniaster test --sanitize` runs (with the unit tests).
  if(_name IN_LIST MINIASTER_ORIGINALS)
    set_tests_properties(original.${_name} PROPERTIES LABELS ssnv511)
  endif()
  # ssnv511a-h on two MPI processes as well: the same TEST results as on one.
  if(_name IN_LIST MINIASTER_ORIGINALS)
    set_tests_properties(original.${_name} PROPERTIES FIXTURES_SETUP one_process.${_name})
    add_test(NAME original_np2.${_name}
             COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${CMAKE_SOURCE_DIR}/../shared/astest/${_name}.export
                     ${CMAKE_BINARY_DIR}/astest-out/np2_${_name} --same-tests-as ${CMAKE_BINARY_DIR}/astest-out/${_name}
                     ${_opt} -- --np 2)
    set_tests_properties(original_np2.${_name} PROPERTIES FIXTURES_REQUIRED one_process.${_name} PROCESSORS 2)
  endif()
endforeach()

# The manufactured fields of the smooth scenes (open and with contact): derivatives against finite
# differences, body force, contact conditions on the interfaces, and mutated fields that must fail
# (tools/study/smooth_field.py). The astest/smooth_* cases trust these fields; ~1 s.
add_test(NAME study.check_field
         COMMAND ${Python_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tools/study/study.py check-field)

# X-FEM volume sub-cells integrated to another degree than the catalogue's (`--subcell-quadrature`,
# docs/xfem.md "Quadrature"): degree 2 keeps every exact answer of the originals (the rigid blocks of
# ssnv511a-d, the uniform stresses with contact of ssnv511e-h, POST_ERREUR's quadratic integrands);
# degree 1 keeps the rigid blocks and, on TRIA3, QUAD4 and TETRA4 parents, the uniform stresses with
# contact (on HEXA8 it fails the patch test, with alarm XFEM_SUBCELL_RULE: tests/cli/xfem_commands.cpp).
foreach(_name ${MINIASTER_ORIGINALS})
  set(_opt "")
  if(_name IN_LIST MINIASTER_ORIGINALS_INEXACT_VALE_CALC)
    set(_opt --allow-nonregression-nook)
  endif()
  add_test(NAME original_subcell_degree2.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${CMAKE_SOURCE_DIR}/../shared/astest/${_name}.export
                   ${CMAKE_BINARY_DIR}/astest-out/subcell_degree2_${_name} ${_opt} -- --subcell-quadrature 2)
endforeach()
foreach(_name ssnv511a ssnv511b ssnv511c ssnv511d)
  add_test(NAME original_subcell_degree1.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${CMAKE_SOURCE_DIR}/../shared/astest/${_name}.export
                   ${CMAKE_BINARY_DIR}/astest-out/subcell_degree1_${_name} -- --subcell-quadrature 1)
endforeach()
foreach(_name contact_quad4_n5 contact_tria3_n7 contact_tetra4_n5)
  add_test(NAME astest_subcell_degree1.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${CMAKE_SOURCE_DIR}/astest/${_name}.export
                   ${CMAKE_BINARY_DIR}/astest-out/subcell_degree1_${_name} -- --subcell-quadrature 1)
endforeach()
add_test(NAME astest_subcell_degree2.contact_hexa8_n5
         COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${CMAKE_SOURCE_DIR}/astest/contact_hexa8_n5.export
                 ${CMAKE_BINARY_DIR}/astest-out/subcell_degree2_contact_hexa8_n5 -- --subcell-quadrature 2)

# Invariants of the 3D F-junction cases read from their four runs' .mess (tests/fjunction_check.py):
# no interpenetration where the answer is exact, the penetration of the stepped loads below 2e-3 m and
# shrinking from N = 7 to 13, every contact solve converged within ITER_CONT_MAXI = 10.
set(_fjunction_runs astest.fjunction_hexa8_n7 astest.fjunction_hexa8_n13 astest.fjunction_tetra4_n7
    astest.fjunction_tetra4_n13)
set_property(TEST ${_fjunction_runs} APPEND PROPERTY FIXTURES_SETUP fjunction)
add_test(NAME astest.fjunction_invariants
         COMMAND ${Python_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/fjunction_check.py ${CMAKE_BINARY_DIR}/astest-out)
set_tests_properties(astest.fjunction_invariants PROPERTIES FIXTURES_REQUIRED fjunction)

# ssnv511h.comm on its own nodes re-split conformingly: exact (tests/resplit_check.sh, docs/mesh.md
# "Conformity"), where code_aster's non-conforming ssnv511h.mmed gives both codes 0.13.
add_test(NAME original_resplit.ssnv511h
         COMMAND ${CMAKE_SOURCE_DIR}/tests/resplit_check.sh $<TARGET_FILE:miniaster-bin> $<TARGET_FILE:resplit_layer>
                 ${CMAKE_SOURCE_DIR}/../shared/astest ${CMAKE_BINARY_DIR}/astest-out/resplit_ssnv511h)

# The originals with other SOLVEUR settings (tests/solveur_variant.py: a copy of the .comm under the
# build folder with SOLVEUR=_F(...) in its solving calls): the same TEST results as the original run,
# and the .mess shows the setting reached the solver (docs/solver.md).
function(miniaster_solveur_variant _label _name _keywords _expect)
  set(_opt "")
  if(_name IN_LIST MINIASTER_ORIGINALS_INEXACT_VALE_CALC)
    set(_opt --allow-nonregression-nook)
  endif()
  add_test(NAME original_solveur_${_label}.${_name}
           COMMAND ${Python_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/solveur_variant.py $<TARGET_FILE:miniaster-bin>
                   ${_run} ${CMAKE_SOURCE_DIR}/../shared/astest ${_name}
                   ${CMAKE_BINARY_DIR}/astest-out/solveur_${_label}_${_name} ${CMAKE_BINARY_DIR}/astest-out/${_name}
                   "${_keywords}" "${_expect}" ${_opt} ${ARGN})
  set_tests_properties(original_solveur_${_label}.${_name} PROPERTIES FIXTURES_REQUIRED one_process.${_name})
endfunction()
foreach(_name ssnv511e ssnv511f ssnv511g ssnv511h)
  miniaster_solveur_variant(mixer_precision ${_name} "METHODE='MUMPS', MIXER_PRECISION='OUI'"
                            "MUMPS (single-precision factors) solve")
endforeach()
miniaster_solveur_variant(filtrage_matrice ssnv511e "METHODE='MUMPS', FILTRAGE_MATRICE=1e-12, MIXER_PRECISION='OUI'"
                          "FILTRAGE_MATRICE=1e-12: ")
miniaster_solveur_variant(resi_rela ssnv511b "METHODE='MUMPS', RESI_RELA=1e-12" "RESI_RELA=1e-12")
miniaster_solveur_variant(out_of_core ssnv511a "METHODE='MUMPS', GESTION_MEMOIRE='OUT_OF_CORE'"
                          "MUMPS out of core (ICNTL(22)=1)")
# METHODE='PETSC' / 'GCPC' (docs/solver.md): ssnv511a-d's references are exact to 1e-13, met with
# RESI_RELA=1e-15; ssnv511e-h go through STAT_NON_LINE's Newton, with RESI_RELA=1e-12 (ssnv511h's
# multipliers keep FGMRES's true residual at ~5e-14: 1e-15 is refused there as unreachable).
foreach(_case "a|cg_gamg|ALGORITHME='CG', PRE_COND='GAMG'|1e-15" "b|cg_gamg|ALGORITHME='CG', PRE_COND='GAMG'|1e-15"
              "b|gmres_boomer|ALGORITHME='GMRES', PRE_COND='BOOMER'|1e-15" "c|cg_ml|ALGORITHME='CG', PRE_COND='ML'|1e-15"
              "a|fgmres_ldlt_sp|PRE_COND='LDLT_SP'|1e-15" "d|cr_sor|ALGORITHME='CR', PRE_COND='SOR'|1e-15"
              "e|fgmres_ldlt_sp|PRE_COND='LDLT_SP'|1e-12" "f|gcr_ldlt_sp|ALGORITHME='GCR', PRE_COND='LDLT_SP'|1e-12"
              "g|gmres_ldlt_dp|ALGORITHME='GMRES', PRE_COND='LDLT_DP'|1e-12" "h|fgmres_ldlt_sp|PRE_COND='LDLT_SP'|1e-12"
              "e|fgmres_gamg|PRE_COND='GAMG'|1e-12")
  string(REPLACE "|" ";" _f "${_case}")
  list(GET _f 0 _letter)
  list(GET _f 1 _label)
  list(GET _f 2 _keywords)
  list(GET _f 3 _resi)
  string(REGEX MATCH "ALGORITHME='[A-Z]+'" _algorithm "${_keywords}")
  if(NOT _algorithm)
    set(_algorithm "ALGORITHME='FGMRES'")
  endif()
  string(REGEX MATCH "PRE_COND='[A-Z_]+'" _pc "${_keywords}")
  miniaster_solveur_variant(petsc_${_label} ssnv511${_letter} "METHODE='PETSC', ${_keywords}, RESI_RELA=${_resi}"
                            "PETSC (${_algorithm}, ${_pc}) solve")
endforeach()
foreach(_case "a|1e-15" "d|1e-15" "e|1e-12")
  string(REPLACE "|" ";" _f "${_case}")
  list(GET _f 0 _letter)
  list(GET _f 1 _resi)
  miniaster_solveur_variant(gcpc_ldlt_inc ssnv511${_letter} "METHODE='GCPC', RESI_RELA=${_resi}"
                            "GCPC (ALGORITHME='CG', PRE_COND='LDLT_INC') solve")
endforeach()
# On two processes each assembles its own cells (MATR_DISTRIBUEE): PETSc multiplies by the sum of
# the parts, LDLT_SP's factors are MUMPS's on both processes, and GAMG, ML and BOOMER share the piece
# basis between the processes (each builds its rows of a parallel matrix): the same TEST results.
foreach(_case "a|ldlt_sp|PRE_COND='LDLT_SP'|1e-15|FGMRES|" "e|ldlt_sp|PRE_COND='LDLT_SP'|1e-12|FGMRES|"
              "a|gamg|ALGORITHME='CG', PRE_COND='GAMG'|1e-15|CG|shared by 2 processes"
              "c|ml|ALGORITHME='CG', PRE_COND='ML'|1e-15|CG|shared by 2 processes"
              "b|boomer|ALGORITHME='GMRES', PRE_COND='BOOMER'|1e-15|GMRES|shared by 2 processes")
  string(REPLACE "|" ";" _f "${_case}")
  list(GET _f 0 _letter)
  list(GET _f 1 _label)
  list(GET _f 2 _keywords)
  list(GET _f 3 _resi)
  list(GET _f 4 _algorithm)
  list(GET _f 5 _shared)
  string(REGEX MATCH "PRE_COND='[A-Z_]+'" _pc "${_keywords}")
  set(_expect "cells partitioned over 2 processes && PETSC (ALGORITHME='${_algorithm}', ${_pc}) solve")
  if(_shared)
    string(APPEND _expect " && ${_shared}")
  endif()
  miniaster_solveur_variant(petsc_np2_${_label} ssnv511${_letter} "METHODE='PETSC', ${_keywords}, RESI_RELA=${_resi}"
                            "${_expect}" -- --np 2)
  set_tests_properties(original_solveur_petsc_np2_${_label}.ssnv511${_letter} PROPERTIES PROCESSORS 2)
endforeach()
# GAMG iterates in the piece basis of the X-FEM model (fe/PieceCopies.hpp): the 3 rigid modes of 2D at
# the node copies, not 3 per colour of the 4 blocks.
miniaster_solveur_variant(petsc_gamg_modes ssnv511a "METHODE='PETSC', ALGORITHME='CG', PRE_COND='GAMG', RESI_RELA=1e-15"
                          "piece basis of the X-FEM model (4 block(s)) && near null space: 3 rigid body modes")

# Beyond ssnv511: each solver on originals of the family, beyond and cracks it applies to (docs/solver.md,
# "Results on the originals"; the whole matrix was run once by hand). RESI_RELA=1e-15 where the
# references are exact to 1e-13 (1e-12 leaves 10 of ssnv512a's 18 NOOK), LDLT_SP on a contact
# STAT_NON_LINE (ssnv201a), ML on a crack-tip model (ssnv198a: the blocks' modes, no piece basis),
# MIXER_PRECISION on STAT_NON_LINE files (MECA_STATIQUE has no such keyword, as in code_aster).
foreach(_case "ssnv512a|petsc_fgmres_ldlt_sp|PRE_COND='LDLT_SP', RESI_RELA=1e-15|PETSC (ALGORITHME='FGMRES', PRE_COND='LDLT_SP') solve"
              "ssnv201a|petsc_fgmres_ldlt_sp|PRE_COND='LDLT_SP', RESI_RELA=1e-15|PETSC (ALGORITHME='FGMRES', PRE_COND='LDLT_SP') solve"
              "ssnv195a|petsc_fgmres_ldlt_sp|PRE_COND='LDLT_SP', RESI_RELA=1e-15|PETSC (ALGORITHME='FGMRES', PRE_COND='LDLT_SP') solve"
              "ssnv513b|petsc_cg_ml|ALGORITHME='CG', PRE_COND='ML', RESI_RELA=1e-15|PETSC (ALGORITHME='CG', PRE_COND='ML') solve"
              "ssnv173d|petsc_cg_ml|ALGORITHME='CG', PRE_COND='ML', RESI_RELA=1e-15|PETSC (ALGORITHME='CG', PRE_COND='ML') solve"
              "ssnv198a|petsc_cg_ml|ALGORITHME='CG', PRE_COND='ML', RESI_RELA=1e-15|PETSC (ALGORITHME='CG', PRE_COND='ML') solve")
  string(REPLACE "|" ";" _f "${_case}")
  list(GET _f 0 _name)
  list(GET _f 1 _label)
  list(GET _f 2 _keywords)
  list(GET _f 3 _expect)
  miniaster_solveur_variant(${_label} ${_name} "METHODE='PETSC', ${_keywords}" "${_expect}")
endforeach()
foreach(_name ssnv513d ssnv203a ssnv191b)
  miniaster_solveur_variant(gcpc_ldlt_inc ${_name} "METHODE='GCPC', RESI_RELA=1e-15"
                            "GCPC (ALGORITHME='CG', PRE_COND='LDLT_INC') solve")
endforeach()
foreach(_name ssnv513h ssnp169a ssnv201a)
  miniaster_solveur_variant(mixer_precision ${_name} "METHODE='MUMPS', MIXER_PRECISION='OUI'"
                            "MUMPS (single-precision factors) solve")
endforeach()
