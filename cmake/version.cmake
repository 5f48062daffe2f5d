# `chainbreak --version`: the project's version and the git commit it was built from, taken
# at configure time (git describe). Without git or a .git (a source tarball) the commit is
# CHAINBREAK_GIT_COMMIT if given, else "unknown".
set(CHAINBREAK_GIT_COMMIT "" CACHE STRING "Commit to report when the source has no .git")
set(CHAINBREAK_COMMIT "${CHAINBREAK_GIT_COMMIT}")
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS ${PROJECT_SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                  OUTPUT_VARIABLE CHAINBREAK_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET RESULT_VARIABLE CHAINBREAK_DESCRIBE_RESULT)
  if(CHAINBREAK_DESCRIBE_RESULT EQUAL 0 AND CHAINBREAK_DESCRIBE)
    set(CHAINBREAK_COMMIT "${CHAINBREAK_DESCRIBE}")
  endif()
endif()
if(NOT CHAINBREAK_COMMIT)
  set(CHAINBREAK_COMMIT "unknown")
endif()
message(STATUS "chainbreak ${PROJECT_VERSION}, commit ${CHAINBREAK_COMMIT}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.h.in ${PROJECT_BINARY_DIR}/generated/version.h @ONLY)
add_library(cb_version INTERFACE)
target_include_directories(cb_version INTERFACE ${PROJECT_BINARY_DIR}/generated)
