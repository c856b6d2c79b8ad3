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
