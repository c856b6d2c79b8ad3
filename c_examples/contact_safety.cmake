# Safety tests of the contact C API (included by CMakeLists.txt inside its examples block, so
# hycon_example / hycon_test / hycon_valgrind_test / hycon_asan_test are defined):
#   contact_bad_input.c  every bad-input class with its status and message, outputs untouched,
#                        failed increments keeping the last converged state (shared and static)
#   contact_threads.c    two independent problems (model API and host API with a solve
#                        callback) from two threads at once == the same one after the other
# Each also runs under valgrind (memcheck) and built with ASan + UBSan; contact_threads also
# under helgrind and DRD.

hycon_example(contact_bad_input contact_bad_input.c C hycon::hycon)
hycon_example(contact_bad_input_static contact_bad_input.c C hycon::hycon_static)
hycon_test(contact_bad_input_shared contact_bad_input)
hycon_test(contact_bad_input_static contact_bad_input_static)
hycon_valgrind_test(valgrind_contact_bad_input contact_bad_input)
hycon_valgrind_test(valgrind_contact_bad_input_static contact_bad_input_static)
hycon_asan_test(contact_bad_input contact_bad_input.c C)

# memcheck false positive in the optimised library: Plate::settle takes
# `solved: Option<(&[usize], &[f64])>`; LLVM compares the two slice lengths (uninitialised when
# the option is None) before it tests the None niche, and both branches end in the same state.
# Scoped to these tests (VALGRIND_OPTS) and to that one function.
set(_hycon_safety_supp "${CMAKE_CURRENT_BINARY_DIR}/contact_safety.supp")
file(WRITE "${_hycon_safety_supp}"
"{
   hycon-plate-settle-none-slice-lengths
   Memcheck:Cond
   fun:*Plate*settle*
}
")
foreach(_t valgrind_contact_bad_input valgrind_contact_bad_input_static)
  if(TEST ${_t})
    set_tests_properties(${_t} PROPERTIES
      ENVIRONMENT "RUST_BACKTRACE=1;VALGRIND_OPTS=--suppressions=${_hycon_safety_supp}")
  endif()
endforeach()

# contact_threads [rounds]: the threaded solves are repeated `rounds` times (default 4)
hycon_example(contact_threads contact_threads.c C hycon::hycon)
target_link_libraries(contact_threads PRIVATE Threads::Threads)
hycon_test(contact_threads contact_threads 8)
hycon_valgrind_test(valgrind_contact_threads contact_threads 1)
hycon_asan_test(contact_threads contact_threads.c C 2)
if(TARGET contact_threads_asan)
  target_link_libraries(contact_threads_asan PRIVATE Threads::Threads)
endif()
# data-race detectors (clean with valgrind's default suppressions; about 3 s each)
if(_vg)
  hycon_test(helgrind_contact_threads "${VALGRIND_EXECUTABLE}" --tool=helgrind --error-exitcode=1
             $<TARGET_FILE:contact_threads> 1)
  hycon_test(drd_contact_threads "${VALGRIND_EXECUTABLE}" --tool=drd --error-exitcode=1
             $<TARGET_FILE:contact_threads> 1)
endif()
