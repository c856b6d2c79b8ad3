# C++ and the contact API (issue 4, items c and d), included by CMakeLists.txt:
# * sliding_cpp: frictional sliding of a half disk on a block through the model API, driven with
#   the header-only RAII wrapper include/hycon.hpp; checks |ts| = mu |tn| at slip nodes, the
#   friction cone at stick nodes, slip directions and Q/P in gross sliding. The argument is the
#   number of elements per contact half-width (default 8; 2 under valgrind, 4 under ASan).
# * header_hpp17 / header_hpp17_noexcept: hycon.hpp alone, included twice, under the warning
#   flags of every example plus -Wshadow -Wconversion -Wold-style-cast ..., once with
#   -fno-exceptions; they also run the wrapper's solve and monitor adapters on a tiny
#   host-assembly problem.

hycon_example(sliding_cpp sliding_cpp.cpp CXX hycon::hycon)
hycon_test(sliding_cpp sliding_cpp)
hycon_valgrind_test(valgrind_sliding_cpp sliding_cpp 2)
hycon_asan_test(sliding_cpp sliding_cpp.cpp CXX 4)

hycon_example(header_hpp17 header_hpp17.cpp CXX hycon::hycon)
hycon_test(header_hpp17 header_hpp17)
hycon_valgrind_test(valgrind_header_hpp17 header_hpp17)
hycon_asan_test(header_hpp17 header_hpp17.cpp CXX)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  # hosts often build with more warnings than these examples: keep the wrapper clean of them
  set(_hycon_hpp_strict -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast -Wcast-qual)
  target_compile_options(header_hpp17 PRIVATE ${_hycon_hpp_strict})
  hycon_example(header_hpp17_noexcept header_hpp17.cpp CXX hycon::hycon)
  target_compile_options(header_hpp17_noexcept PRIVATE -fno-exceptions ${_hycon_hpp_strict})
  hycon_test(header_hpp17_noexcept header_hpp17_noexcept)
  hycon_valgrind_test(valgrind_header_hpp17_noexcept header_hpp17_noexcept)
endif()

# shrink_host_cpp: the axisymmetric shrink fit of shrink_fit.c through the host-assembly API
# (CSR from hycon::element_stiffness in axisymmetric mode), against Lame and the model API.
# The argument is the number of elements through each wall (default 8).
hycon_example(shrink_host_cpp shrink_host_cpp.cpp CXX hycon::hycon)
hycon_test(shrink_host_cpp shrink_host_cpp)
hycon_valgrind_test(valgrind_shrink_host_cpp shrink_host_cpp 4)
hycon_asan_test(shrink_host_cpp shrink_host_cpp.cpp CXX)
