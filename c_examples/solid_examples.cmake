# The 3D element routines (issue #36): a C host assembling brick stiffnesses into CSR, included
# by CMakeLists.txt in its examples block (hycon_example, hycon_test, hycon_valgrind_test and
# hycon_asan_test are defined there). Fails on wrong numbers ("wrong value", exit code 1).
hycon_example(brick_cantilever brick_cantilever.c C hycon::hycon)
hycon_test(brick_cantilever brick_cantilever)
hycon_valgrind_test(valgrind_brick_cantilever brick_cantilever 6)
hycon_asan_test(brick_cantilever brick_cantilever.c C)
# the same routines from C++17 through hycon.hpp: MacNeal-Harder's regular cantilever
hycon_example(brick_macneal_cpp brick_macneal_cpp.cpp CXX hycon::hycon)
hycon_test(brick_macneal_cpp brick_macneal_cpp)
hycon_valgrind_test(valgrind_brick_macneal_cpp brick_macneal_cpp)
hycon_asan_test(brick_macneal_cpp brick_macneal_cpp.cpp CXX)
# MacNeal-Harder's 3D patch test at full distortion from C (issue #42): the shape policy's
# warnings and errors (hycon_brick_shape), both bricks exact
hycon_example(brick_patch brick_patch.c C hycon::hycon)
hycon_test(brick_patch brick_patch)
hycon_valgrind_test(valgrind_brick_patch brick_patch)
hycon_asan_test(brick_patch brick_patch.c C)
# the same C host solving with CHOLMOD (brick_cantilever.c with HYCON_EXAMPLE_CHOLMOD), where
# contact_examples.cmake found SuiteSparse; checked against its conjugate gradients
if(HYCON_CHOLMOD_INCLUDE_DIR AND HYCON_CHOLMOD_LIBRARY)
  hycon_example(brick_cantilever_cholmod brick_cantilever.c C hycon::hycon)
  hycon_test(brick_cantilever_cholmod brick_cantilever_cholmod)
  hycon_valgrind_test(valgrind_brick_cantilever_cholmod brick_cantilever_cholmod 6)
  hycon_asan_test(brick_cantilever_cholmod brick_cantilever.c C)
  foreach(_brick_target brick_cantilever_cholmod brick_cantilever_cholmod_asan)
    if(TARGET ${_brick_target})
      target_compile_definitions(${_brick_target} PRIVATE HYCON_EXAMPLE_CHOLMOD)
      target_include_directories(${_brick_target} SYSTEM PRIVATE "${HYCON_CHOLMOD_INCLUDE_DIR}")
      target_link_libraries(${_brick_target} PRIVATE "${HYCON_CHOLMOD_LIBRARY}")
    endif()
  endforeach()
else()
  message(STATUS "CHOLMOD not found: example brick_cantilever_cholmod skipped")
endif()
# 3D contact, model family (issue #43): Hertz's quarter cap on a block built in C, pressed
# frictionless (checked against Hertz: radius, peak pressure, load; A's and B's forces
# balanced), and the bad-input paths of hycon_solid_model_* / hycon_solid_contact_* (statuses,
# messages, outputs untouched). The Hertz run factors some 25000 dofs, large enough for the
# nested-dissection trial, and METIS is loaded with RTLD_DEEPBIND, which the sanitizer runtime
# refuses: no ASan variant; under valgrind it is clean but takes 2 minutes (measured 1m56s), so
# no valgrind variant either. The bad-input test has both.
hycon_example(solid_hertz solid_hertz.c C hycon::hycon)
hycon_test(solid_hertz solid_hertz)
hycon_example(solid_contact_bad_input solid_contact_bad_input.c C hycon::hycon)
hycon_example(solid_contact_bad_input_static solid_contact_bad_input.c C hycon::hycon_static)
hycon_test(solid_contact_bad_input_shared solid_contact_bad_input)
hycon_test(solid_contact_bad_input_static solid_contact_bad_input_static)
hycon_valgrind_test(valgrind_solid_contact_bad_input solid_contact_bad_input)
hycon_asan_test(solid_contact_bad_input solid_contact_bad_input.c C)
# 3D contact, host family (issue #43): a C host's own bricks (hycon_brick_stiffness), equation
# numbering and dense Cholesky, the contact patch test of a stack through hycon_solid_host_*
# (CSR and solve callback), checked against its closed form
hycon_example(solid_host solid_host.c C hycon::hycon)
hycon_test(solid_host solid_host)
hycon_valgrind_test(valgrind_solid_host solid_host)
hycon_asan_test(solid_host solid_host.c C)
