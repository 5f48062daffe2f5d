# libchainbreak-core.so: the libraries with no render stack (physics, drive, exact, scene,
# figures as data, cluster, the commands run/sweep/merge, ...) as ONE shared library, linked by
# the program, by the picture module chainbreak-pictures.so (src/app/picture_commands.h), by the
# Python module, the viewer, the tests and the benchmarks.
#
# Why one shared library: the program starts with no render stack, and the module that has it
# needs the same core. Linked statically into both, the core's code and globals (the interrupt
# flag) existed twice, and the program had to export its copies for the module to bind to.
# Here there is one copy, loaded once, and each library still has its own target per folder:
#
#   cb_core_library(cb_physics a.cpp b.cpp)
#     cb_physics_code  the folder's objects (OBJECT library); its links to other *_code
#                      targets state the layering inside the core, and only the core links them
#     cb_physics       what every other target links (INTERFACE): the shared core
#
# So `target_link_libraries(x PUBLIC cb_physics)` keeps meaning "x uses the physics" wherever
# it is written, and no target can get a second copy of the core's objects.
#
# Speed: calls inside the core must not become calls through the PLT, nor lose inlining. The
# objects are compiled with -fno-semantic-interposition (the compiler may inline and call a
# global function of the core directly) and the library is linked with -Bsymbolic-functions
# (its own functions bind to themselves at link time). Data keeps the default binding, so a
# global the program reads through a copy relocation (cb::g_interrupted) stays one object.
# Measured against the static build in tests/bench/README.md (issue 13).

# Where cmake --install puts the program's private libraries: this one and the picture module
# (bin -> lib/chainbreak; the programs find them by an RPATH relative to themselves).
include(GNUInstallDirs)
set(CHAINBREAK_LIB_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/chainbreak
    CACHE INTERNAL "Where cmake --install puts libchainbreak-core.so and chainbreak-pictures.so")

# Sanitizer builds leave the runtime's symbols to the program that links it, so a shared object
# of theirs has undefined symbols by design: --no-undefined only in the other builds.
if(CHAINBREAK_FUZZ OR CMAKE_CXX_FLAGS MATCHES "-fsanitize")
  set(CHAINBREAK_SANITIZED ON)
else()
  set(CHAINBREAK_SANITIZED OFF)
endif()

add_library(chainbreak_core SHARED)
target_include_directories(chainbreak_core PUBLIC ${PROJECT_SOURCE_DIR}/src)
target_link_libraries(chainbreak_core PUBLIC Threads::Threads)
target_link_options(chainbreak_core PRIVATE -Wl,-Bsymbolic-functions)
if(NOT CHAINBREAK_SANITIZED)
  target_link_options(chainbreak_core PRIVATE -Wl,--no-undefined)
endif()
set_target_properties(chainbreak_core PROPERTIES OUTPUT_NAME chainbreak-core
                      LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR})
install(TARGETS chainbreak_core LIBRARY DESTINATION ${CHAINBREAK_LIB_INSTALL_DIR} NAMELINK_SKIP
        COMPONENT cli)

# cb_core_library(NAME SOURCES...): NAME_code (the objects, in the core) and NAME (the core).
function(cb_core_library name)
  add_library(${name}_code OBJECT ${ARGN})
  target_include_directories(${name}_code PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_compile_options(${name}_code PRIVATE -fno-semantic-interposition)
  target_link_libraries(chainbreak_core PRIVATE ${name}_code)
  add_library(${name} INTERFACE)
  target_link_libraries(${name} INTERFACE chainbreak_core)
endfunction()

# cb_install_rpath(TARGET DESTINATION): once installed in DESTINATION (relative to the prefix),
# TARGET finds libchainbreak-core.so relative to itself, wherever the prefix is.
function(cb_install_rpath target destination)
  file(RELATIVE_PATH to_lib /${destination} /${CHAINBREAK_LIB_INSTALL_DIR})
  if(to_lib STREQUAL "")
    set(rpath "$ORIGIN")
  else()
    set(rpath "$ORIGIN/${to_lib}")
  endif()
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "${rpath}")
endfunction()
