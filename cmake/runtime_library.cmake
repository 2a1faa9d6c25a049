# hexgait_runtime_library(VAR NAME [HINT_DIR...]): finds the library the linker would take for
# NAME (-lNAME) and defines VAR as the C initialiser {"SONAME", "DEBIAN_PACKAGE"}, for
# util/shared_library.h: hexgait opens these libraries with dlopen when a command first needs
# them, so it needs the name the dynamic loader knows (the SONAME, read with objdump) and, for
# the error message when it is missing, the package that installs it (dpkg; "" elsewhere).
function(hexgait_runtime_library var name)
  find_library(library NAMES ${name} HINTS ${ARGN} NO_CACHE)
  if(NOT library)
    message(FATAL_ERROR "hexgait: lib${name} not found (scripts/deps.sh installs it)")
  endif()
  execute_process(COMMAND ${CMAKE_OBJDUMP} -p ${library} OUTPUT_VARIABLE dump ERROR_QUIET)
  if(NOT dump MATCHES "SONAME +([^\n ]+)")
    message(FATAL_ERROR "hexgait: cannot read the SONAME of ${library}")
  endif()
  set(soname ${CMAKE_MATCH_1})
  set(package "")
  get_filename_component(real ${library} REALPATH)
  find_program(HEXGAIT_DPKG_QUERY dpkg-query)
  if(HEXGAIT_DPKG_QUERY)
    execute_process(COMMAND ${HEXGAIT_DPKG_QUERY} -S ${real} OUTPUT_VARIABLE owner ERROR_QUIET)
    if(owner MATCHES "^([^:,]+)")
      set(package ${CMAKE_MATCH_1})
    endif()
  endif()
  set(${var} "{\"${soname}\", \"${package}\"}" PARENT_SCOPE)
  message(STATUS "hexgait: ${name} loaded on demand as ${soname} (${package})")
endfunction()
