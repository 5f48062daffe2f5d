# `chainbreak --version`: the project's version and the git commit it was built from
# (git describe --dirty). src/cmake/git_version.cmake writes generated/version.h at every build
# and rewrites it only when the text changes, so a new commit shows without reconfiguring and
# an unchanged one rebuilds nothing. Without git or a .git (a source tarball) the commit is
# CHAINBREAK_GIT_COMMIT if given, else "unknown".
set(CHAINBREAK_GIT_COMMIT "" CACHE STRING "Commit to report when the source has no .git")
find_package(Git QUIET)
set(CHAINBREAK_VERSION_HEADER ${PROJECT_BINARY_DIR}/generated/version.h)
set(CHAINBREAK_VERSION_ARGS -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUT=${CHAINBREAK_VERSION_HEADER}
    -DVERSION=${PROJECT_VERSION} -DGIT=${GIT_EXECUTABLE} -DFALLBACK=${CHAINBREAK_GIT_COMMIT}
    -DTEMPLATE=${CMAKE_CURRENT_LIST_DIR}/version.h.in)
execute_process(COMMAND ${CMAKE_COMMAND} ${CHAINBREAK_VERSION_ARGS}
                -P ${CMAKE_CURRENT_LIST_DIR}/git_version.cmake)  # present before the first build
add_custom_target(cb_version_header
  COMMAND ${CMAKE_COMMAND} ${CHAINBREAK_VERSION_ARGS} -P ${CMAKE_CURRENT_LIST_DIR}/git_version.cmake
  BYPRODUCTS ${CHAINBREAK_VERSION_HEADER}
  COMMENT "chainbreak version and git commit")
add_library(cb_version INTERFACE)
target_include_directories(cb_version INTERFACE ${PROJECT_BINARY_DIR}/generated)
add_dependencies(cb_version cb_version_header)  # its users are built after the header
