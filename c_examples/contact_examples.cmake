# The contact examples in C (issue #4, items 4a and 4b), included by CMakeLists.txt in its
# examples block, where hycon_example, hycon_test, hycon_valgrind_test and hycon_asan_test are
# defined. Each test fails on wrong numbers (exit code 1, and FAILED / "wrong value" printed).
# The valgrind runs use coarser meshes (the argument: elements per contact half-width) so each
# stays well under a minute; the ASan+UBSan runs use the default meshes.

# 4a: Hertz disk on block through the model API (mesh built in C, force control via a plate)
hycon_example(hertz_model hertz_model.c C hycon::hycon)
hycon_test(hertz_model hertz_model)
hycon_valgrind_test(valgrind_hertz_model hertz_model 8)
hycon_asan_test(hertz_model hertz_model.c C)
# the same analysis factored by CHOLMOD, when the library has the suitesparse feature
if(HYCON_CARGO_FEATURES MATCHES "suitesparse")
  hycon_test(hertz_model_cholmod hertz_model 12 cholmod)
endif()

# axisymmetric: the shrink fit of two thick tubes through the model API (an initial overlap,
# Lame's pressure)
hycon_example(shrink_fit shrink_fit.c C hycon::hycon)
hycon_test(shrink_fit shrink_fit)
hycon_valgrind_test(valgrind_shrink_fit shrink_fit 4)
hycon_asan_test(shrink_fit shrink_fit.c C)

# 4b: a host with its own Q4 elements and CHOLMOD (Debian's libsuitesparse-dev has no CMake or
# pkg-config file: find the header and the library directly), through the solve callback,
# checked against the CSR path and the model API
find_path(HYCON_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse
          DOC "directory of cholmod.h (SuiteSparse)")
find_library(HYCON_CHOLMOD_LIBRARY cholmod DOC "the CHOLMOD library (SuiteSparse)")
if(HYCON_CHOLMOD_INCLUDE_DIR AND HYCON_CHOLMOD_LIBRARY)
  hycon_example(cholmod_host cholmod_host.c C hycon::hycon)
  target_include_directories(cholmod_host SYSTEM PRIVATE "${HYCON_CHOLMOD_INCLUDE_DIR}")
  target_link_libraries(cholmod_host PRIVATE "${HYCON_CHOLMOD_LIBRARY}")
  hycon_test(cholmod_host cholmod_host)
  # the press under finite kinematics with friction (the host's `small|finite mu` arguments)
  hycon_test(cholmod_host_finite_friction cholmod_host 8 finite 0.3)
  hycon_valgrind_test(valgrind_cholmod_host cholmod_host 4)
  hycon_asan_test(cholmod_host cholmod_host.c C)
  if(TARGET cholmod_host_asan)
    target_include_directories(cholmod_host_asan SYSTEM PRIVATE "${HYCON_CHOLMOD_INCLUDE_DIR}")
    target_link_libraries(cholmod_host_asan PRIVATE "${HYCON_CHOLMOD_LIBRARY}")
  endif()
else()
  message(STATUS "CHOLMOD not found (Debian: apt-get install libsuitesparse-dev): "
                 "example cholmod_host skipped")
endif()
