# CMake package configuration for hycon (hand-written: the library is built by cargo, so there
# is no CMake-built target to install(EXPORT)). Relocatable through 
####### Expanded from @PACKAGE_INIT@ by configure_package_config_file() #######
####### Any changes to this file will be overwritten by the next CMake run ####
####### The input file was hyconConfig.cmake.in                            ########

get_filename_component(PACKAGE_PREFIX_DIR "${CMAKE_CURRENT_LIST_DIR}/../../../" ABSOLUTE)

macro(set_and_check _var _file)
  set(${_var} "${_file}")
  if(NOT EXISTS "${_file}")
    message(FATAL_ERROR "File or directory ${_file} referenced by variable ${_var} does not exist !")
  endif()
endmacro()

macro(check_required_components _NAME)
  foreach(comp ${${_NAME}_FIND_COMPONENTS})
    if(NOT ${_NAME}_${comp}_FOUND)
      if(${_NAME}_FIND_REQUIRED_${comp})
        set(${_NAME}_FOUND FALSE)
      endif()
    endif()
  endforeach()
endmacro()

####################################################################################.
#
#   find_package(hycon 0.3 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE hycon::hycon)          # shared libhycon.so
#   target_link_libraries(app PRIVATE hycon::hycon_static)   # static libhycon.a

####### Expanded from @PACKAGE_INIT@ by configure_package_config_file() #######
####### Any changes to this file will be overwritten by the next CMake run ####
####### The input file was hyconConfig.cmake.in                            ########

get_filename_component(PACKAGE_PREFIX_DIR "${CMAKE_CURRENT_LIST_DIR}/../../../" ABSOLUTE)

macro(set_and_check _var _file)
  set(${_var} "${_file}")
  if(NOT EXISTS "${_file}")
    message(FATAL_ERROR "File or directory ${_file} referenced by variable ${_var} does not exist !")
  endif()
endmacro()

macro(check_required_components _NAME)
  foreach(comp ${${_NAME}_FIND_COMPONENTS})
    if(NOT ${_NAME}_${comp}_FOUND)
      if(${_NAME}_FIND_REQUIRED_${comp})
        set(${_NAME}_FOUND FALSE)
      endif()
    endif()
  endforeach()
endmacro()

####################################################################################

include(CMakeFindDependencyMacro)
find_dependency(Threads)

set_and_check(hycon_INCLUDE_DIR "${PACKAGE_PREFIX_DIR}/include")
set_and_check(hycon_LIBRARY_DIR "${PACKAGE_PREFIX_DIR}/lib")

if(NOT TARGET hycon::hycon)
  add_library(hycon::hycon SHARED IMPORTED)
  set_target_properties(hycon::hycon PROPERTIES
    IMPORTED_LOCATION "${hycon_LIBRARY_DIR}/libhycon.so"
    IMPORTED_SONAME "libhycon.so"
    INTERFACE_INCLUDE_DIRECTORIES "${hycon_INCLUDE_DIR}")
endif()

if(NOT TARGET hycon::hycon_static)
  add_library(hycon::hycon_static STATIC IMPORTED)
  set_target_properties(hycon::hycon_static PROPERTIES
    IMPORTED_LOCATION "${hycon_LIBRARY_DIR}/libhycon.a"
    INTERFACE_INCLUDE_DIRECTORIES "${hycon_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "Threads::Threads;${CMAKE_DL_LIBS};m;rt;util;gcc_s;cholmod")
endif()

set(hycon_LIBRARIES hycon::hycon)
check_required_components(hycon)
