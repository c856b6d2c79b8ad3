# The load and check routines (issue 42): consistent nodal forces of edge and face loads,
# volume, scaled Jacobian and stress at natural coordinates of plane, axisymmetric and brick
# elements, used from strict C99 against closed forms, with a small host solving Lamé's cylinder
# loaded through them. Included by CMakeLists.txt in its examples block (hycon_example,
# hycon_test, hycon_valgrind_test and hycon_asan_test are defined there). Fails on wrong numbers
# ("wrong value", exit code 1).
hycon_example(loads_c loads_c.c C hycon::hycon)
hycon_test(loads_c loads_c)
hycon_valgrind_test(valgrind_loads_c loads_c)
hycon_asan_test(loads_c loads_c.c C)
