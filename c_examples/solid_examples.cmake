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
# 3D contact, model family (issue #43), through hycon_solid_model_* / hycon_solid_contact_*:
# * solid_hertz [a/h]: Hertz's quarter cap on a block built in C, pressed frictionless, checked
#   against Hertz (radius, peak pressure, load; A's and B's forces balanced). At a/h = 4 it
#   factors some 25000 dofs, enough for the automatic ordering's nested-dissection trial, which
#   loads METIS with dlopen(RTLD_DEEPBIND) except under a sanitizer runtime (which refuses that
#   flag: AMD is kept, src/solver/ordering.rs): the plain and ASan+UBSan runs take a/h = 4, the
#   valgrind run a/h = 2 with its own tolerances (at a/h = 4 it was clean but took 1 min 56 s).
# * solid_block_cpp [n]: a block pressed on a flat and dragged with friction from C++17 through
#   hycon.hpp (SolidModel, SolidContact): the uniform stress of the press exactly, the cone, the
#   slip law, Q/P = mu in gross sliding.
# * solid_contact_bad_input: the bad-input paths (statuses, messages, outputs untouched).
# * solid_randomized [seconds] [seed] [max_rounds]: random small 3D presses invariant under
#   rigid rotation, renumbering and unit rescaling, random bad calls refused without effect.
# CPU seconds measured (release library, user time): valgrind_solid_hertz 17.5,
# valgrind_solid_randomized 5.6, valgrind_solid_block_cpp 3.8, solid_randomized and its ASan run
# 3 each (their time bound), the others under a second each: about 37 CPU seconds for all the
# 3D tests together.
hycon_example(solid_hertz solid_hertz.c C hycon::hycon)
hycon_test(solid_hertz solid_hertz)
hycon_valgrind_test(valgrind_solid_hertz solid_hertz 2)
hycon_asan_test(solid_hertz solid_hertz.c C)

hycon_example(solid_block_cpp solid_block_cpp.cpp CXX hycon::hycon)
hycon_example(solid_block_cpp_static solid_block_cpp.cpp CXX hycon::hycon_static)
hycon_test(solid_block_cpp_shared solid_block_cpp)
hycon_test(solid_block_cpp_static solid_block_cpp_static 4)
hycon_valgrind_test(valgrind_solid_block_cpp solid_block_cpp 4)
hycon_asan_test(solid_block_cpp solid_block_cpp.cpp CXX 4)

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

hycon_example(solid_randomized solid_randomized.c C hycon::hycon)
# (at most 150 rounds of seed 1 and of seed 3, which pass; round 106 of seed 1 settled on a
# numbering-dependent state before 0.13.0, see docs/validation.md)
hycon_test(solid_randomized solid_randomized 3 1 150)
hycon_valgrind_test(valgrind_solid_randomized solid_randomized 120 2 4)
hycon_asan_test(solid_randomized solid_randomized.c C 3 3 150)
