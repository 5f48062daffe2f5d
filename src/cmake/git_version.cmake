# Writes OUT from TEMPLATE with CHAINBREAK_VERSION and CHAINBREAK_COMMIT (src/cmake/version.cmake).
# Run with cmake -P: -DSOURCE_DIR -DOUT -DVERSION -DGIT -DFALLBACK -DTEMPLATE.
set(PROJECT_VERSION "${VERSION}")
set(CHAINBREAK_COMMIT "${FALLBACK}")
if(GIT AND EXISTS ${SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT} describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE describe OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET RESULT_VARIABLE status)
  if(status EQUAL 0 AND describe)
    set(CHAINBREAK_COMMIT "${describe}")
  endif()
endif()
if(NOT CHAINBREAK_COMMIT)
  set(CHAINBREAK_COMMIT "unknown")
endif()
configure_file(${TEMPLATE} ${OUT} @ONLY)  # leaves the file alone when the text is the same
