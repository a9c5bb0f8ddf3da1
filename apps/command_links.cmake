# softpack-<name> -> softpack in DIR, for each name of COMMANDS (comma-separated;
# apps/CMakeLists.txt's SOFTPACK_COMMANDS).
string(REPLACE "," ";" COMMANDS "${COMMANDS}")
foreach(command ${COMMANDS})
  file(CREATE_LINK softpack "${DIR}/softpack-${command}" SYMBOLIC)
endforeach()
