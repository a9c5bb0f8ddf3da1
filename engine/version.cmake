# Writes softpack_version.hpp with `git describe` of the source tree (suffix -dirty when it has
# uncommitted changes), so every output file can record the exact code it came from.
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE GIT_DESCRIBE
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE GIT_RESULT)
if(NOT GIT_RESULT EQUAL 0 OR GIT_DESCRIBE STREQUAL "")
  set(GIT_DESCRIBE "unknown")
endif()
set(CONTENT "#pragma once\n#define SOFTPACK_VERSION \"${PROJECT_VERSION}\"\n#define SOFTPACK_GIT \"${GIT_DESCRIBE}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} OLD)
endif()
if(NOT "${OLD}" STREQUAL "${CONTENT}")
  file(WRITE ${OUTPUT} "${CONTENT}")
endif()
