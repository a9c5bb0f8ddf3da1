# Writes softpack_version.hpp with `git describe` of the source tree (suffix -dirty when it has
# uncommitted changes), so every output file can record the exact code it came from. Changes
# under data/ do not count: they are results the workflow writes (a study rewrites its committed
# runs as it goes, and the runs after the first would otherwise call clean code dirty).
execute_process(COMMAND git describe --always --tags
                WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE GIT_DESCRIBE
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE GIT_RESULT)
if(NOT GIT_RESULT EQUAL 0 OR GIT_DESCRIBE STREQUAL "")
  set(GIT_DESCRIBE "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no -- . ":(exclude)data"
                  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE GIT_CHANGES
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE GIT_STATUS_RESULT)
  if(NOT GIT_STATUS_RESULT EQUAL 0 OR NOT GIT_CHANGES STREQUAL "")
    string(APPEND GIT_DESCRIBE "-dirty")
  endif()
endif()
set(CONTENT "#pragma once\n#define SOFTPACK_VERSION \"${PROJECT_VERSION}\"\n#define SOFTPACK_GIT \"${GIT_DESCRIBE}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} OLD)
endif()
if(NOT "${OLD}" STREQUAL "${CONTENT}")
  file(WRITE ${OUTPUT} "${CONTENT}")
endif()
