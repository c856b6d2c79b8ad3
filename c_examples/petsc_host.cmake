# A PETSc program over MPI drives hycon's contact iteration (issue #14): c_examples/petsc_host.c.
# Included by CMakeLists.txt in its examples block (hycon_example, hycon_test, _vg defined
# there). Built only when PETSc (pkg-config PETSc or petsc; Debian: apt-get install petsc-dev,
# which brings Open MPI and MUMPS) and MPI for C are found.
#
# Tests:
#   petsc_host_np1, petsc_host_np2   mpiexec -n 1 / -n 2 petsc_host 8
#   valgrind_petsc_host              the serial case without mpiexec (MPI singleton), under
#                                    valgrind with c_examples/petsc_mpi.supp (Open MPI's and
#                                    PETSc's own reports only; never a hycon frame)
# Open MPI refuses to run as root (CI does) and to start more ranks than cores unless told:
# the tests set OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM) and OMPI_MCA_rmaps_base_oversubscribe, which
# other MPI implementations ignore. One BLAS/OpenMP thread per rank: MUMPS's threads and the
# ranks would otherwise compete for the same cores.

# scripts/test-all.sh sets HYCON_REQUIRE_PETSC=ON: there a missing PETSc is an error, not a
# silently skipped example.
option(HYCON_REQUIRE_PETSC "Fail the configure when PETSc or MPI is missing" OFF)
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_search_module(HYCON_PETSC IMPORTED_TARGET PETSc petsc)
endif()
find_package(MPI QUIET COMPONENTS C)
if(HYCON_PETSC_FOUND AND MPI_C_FOUND AND MPIEXEC_EXECUTABLE)
  hycon_example(petsc_host petsc_host.c C hycon::hycon)
  target_link_libraries(petsc_host PRIVATE PkgConfig::HYCON_PETSC MPI::MPI_C)
  set(_hycon_mpi_env
    "RUST_BACKTRACE=1"
    "OMPI_ALLOW_RUN_AS_ROOT=1" "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"
    "OMPI_MCA_rmaps_base_oversubscribe=1"
    "OMP_NUM_THREADS=1" "OPENBLAS_NUM_THREADS=1")
  foreach(_np 1 2)
    hycon_test(petsc_host_np${_np} "${MPIEXEC_EXECUTABLE}" ${MPIEXEC_NUMPROC_FLAG} ${_np}
               ${MPIEXEC_PREFLAGS} $<TARGET_FILE:petsc_host> ${MPIEXEC_POSTFLAGS} 8)
    set_tests_properties(petsc_host_np${_np} PROPERTIES
      ENVIRONMENT "${_hycon_mpi_env}" PROCESSORS ${_np} TIMEOUT 300)
  endforeach()
  if(_vg)
    hycon_test(valgrind_petsc_host ${_vg} --num-callers=40
               "--suppressions=${CMAKE_CURRENT_SOURCE_DIR}/c_examples/petsc_mpi.supp"
               $<TARGET_FILE:petsc_host> 4)
    set_tests_properties(valgrind_petsc_host PROPERTIES
      ENVIRONMENT "${_hycon_mpi_env}" TIMEOUT 600)
  endif()
  message(STATUS "PETSc ${HYCON_PETSC_VERSION} and MPI found: example petsc_host "
                 "(mpiexec: ${MPIEXEC_EXECUTABLE})")
elseif(HYCON_REQUIRE_PETSC)
  message(FATAL_ERROR "PETSc or MPI not found (Debian: apt-get install petsc-dev), and "
                      "HYCON_REQUIRE_PETSC is ON")
else()
  message(STATUS "PETSc or MPI not found (Debian: apt-get install petsc-dev): "
                 "example petsc_host skipped")
endif()
