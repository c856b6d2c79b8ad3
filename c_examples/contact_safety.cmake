# Safety tests of the contact C API (included by CMakeLists.txt inside its examples block, so
# hycon_example / hycon_test / hycon_valgrind_test / hycon_asan_test are defined):
#   contact_bad_input.c  every bad-input class with its status and message, outputs untouched,
#                        failed increments keeping the last converged state (shared and static)
#   contact_randomized.c random problems and random bad calls (see below)
#   contact_threads.c    two independent problems (model API and host API with a solve
#                        callback) from two threads at once == the same one after the other,
#                        and const queries on one handle from two threads at once
# Each also runs under valgrind (memcheck) and built with ASan + UBSan; contact_threads also
# under helgrind and DRD.

hycon_example(contact_bad_input contact_bad_input.c C hycon::hycon)
hycon_example(contact_bad_input_static contact_bad_input.c C hycon::hycon_static)
hycon_test(contact_bad_input_shared contact_bad_input)
hycon_test(contact_bad_input_static contact_bad_input_static)
hycon_valgrind_test(valgrind_contact_bad_input contact_bad_input)
hycon_asan_test(contact_bad_input contact_bad_input.c C)
# a library without the suitesparse feature must refuse the CHOLMOD backend (checked in C here;
# the Rust tests run with the feature)
if(NOT HYCON_CARGO_FEATURES MATCHES "suitesparse")
  foreach(_t contact_bad_input contact_bad_input_static contact_bad_input_asan)
    if(TARGET ${_t})
      target_compile_definitions(${_t} PRIVATE HYCON_WITHOUT_CHOLMOD)
    endif()
  endforeach()
endif()

# contact_threads [rounds]: the threaded solves are repeated `rounds` times (default 4)
hycon_example(contact_threads contact_threads.c C hycon::hycon)
target_link_libraries(contact_threads PRIVATE Threads::Threads)
hycon_test(contact_threads contact_threads 8)
hycon_valgrind_test(valgrind_contact_threads contact_threads 1)
hycon_asan_test(contact_threads contact_threads.c C 2)
if(TARGET contact_threads_asan)
  target_link_libraries(contact_threads_asan PRIVATE Threads::Threads)
endif()
# data-race detectors (clean with valgrind's default suppressions; about 3 s each). The second
# argument 0 skips the concurrent const queries on one handle: helgrind and DRD do not model
# the atomics and futexes of Rust's OnceLock and Mutex that synchronize them (they would report
# every access as a race); the plain, ASan and memcheck runs do them.
if(_vg)
  hycon_test(helgrind_contact_threads "${VALGRIND_EXECUTABLE}" --tool=helgrind --error-exitcode=1
             $<TARGET_FILE:contact_threads> 1 0)
  hycon_test(drd_contact_threads "${VALGRIND_EXECUTABLE}" --tool=drd --error-exitcode=1
             $<TARGET_FILE:contact_threads> 1 0)
endif()

# contact_randomized [seconds] [seed] [max_rounds]: random two-block problems through the model
# API: zero increments, invariance under translation, unit scaling and renumbering, and random
# bad calls that must change nothing (seeded, bounded in time)
hycon_example(contact_randomized contact_randomized.c C hycon::hycon)
hycon_test(contact_randomized contact_randomized 3 1)
hycon_valgrind_test(valgrind_contact_randomized contact_randomized 120 2 25)
hycon_asan_test(contact_randomized contact_randomized.c C 3 3)
