# Validation runs: whole .comm files executed by the miniaster binary.
#
# 1. Every project case astest/<case>.export is a test. It must end with exit status 0, unless its
#    .export declares `P expected_diag NOOK_TEST_RESU` (exit 2 expected) — code_aster's own
#    convention for cases that are meant to fail a TEST.
# 2. The originals in ../shared/astest that miniaster supports are listed explicitly below.
set(_run ${CMAKE_SOURCE_DIR}/tools/run_validation.sh)
file(GLOB _cases CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/astest/*.export)
foreach(_export ${_cases})
  get_filename_component(_name ${_export} NAME_WE)
  add_test(NAME astest.${_name}
           COMMAND ${_run} $<TARGET_FILE:miniaster-bin> ${_export} ${CMAKE_BINARY_DIR}/astest-out/${_name})
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
# Originals whose NON_REGRESSION values are code_aster's own inexact results (docs/contact.md,
# docs/family.md): exit 2 accepted when every reference check is OK (tools/run_validation.sh).
set(MINIASTER_ORIGINALS_INEXACT_VALE_CALC ssnv511e ssnv511f ssnv511g ssnv511h ssnv512f ssnv513e ssnv513g
    ssnp169a CACHE INTERNAL "")
# The one reference check allowed to stay NOOK: ssnv513e's ANALYTIQUE envelope -(X+5)/100 +- 0.06 of
# DEPZON_4 DX-DX MAX, which the converged solution itself exceeds (0.0629 at N = 81, the refinement
# study of docs/family.md). Its DEPZON_1 DX-DX MAX line is OK (0.044) and is not excused.
set(_ssnv513e_allowed --allow-reference-nook "TEST_TABLE (ssnv513e.comm line 332) DEPZON_4 DX-DX MAX")
foreach(_name ${MINIASTER_ORIGINALS} ${MINIASTER_FAMILY} ${MINIASTER_BEYOND})
  set(_opt "")
  if(_name IN_LIST MINIASTER_ORIGINALS_INEXACT_VALE_CALC)
    set(_opt --allow-nonregression-nook)
  endif()
  if(_name STREQUAL "ssnv513e")
    list(APPEND _opt ${_ssnv513e_allowed})
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
