cmake_minimum_required(VERSION 3.20)
# Writes the header that `impm --version` reads: the project's version and the commit the
# build was made from (with "+changes" when the work tree differed from it).  Run at every
# build (a script target); the header is rewritten only when it changed, so that nothing
# recompiles.  Outside a git work tree the commit is "unknown".
#   cmake -DSOURCE_DIR=... -DOUTPUT=... -DVERSION=... -P Version.cmake
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse --short=12 HEAD
                OUTPUT_VARIABLE IMPM_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE failed ERROR_QUIET)
if(failed)
  set(IMPM_COMMIT "unknown")
else()
  execute_process(COMMAND git -C "${SOURCE_DIR}" diff --quiet HEAD --
                  RESULT_VARIABLE changed ERROR_QUIET)
  if(changed)
    string(APPEND IMPM_COMMIT "+changes")
  endif()
endif()
string(CONCAT text "#pragma once\n// Written by cmake/Version.cmake at build time.\n"
       "#define IMPM_VERSION \"${VERSION}\"\n#define IMPM_COMMIT \"${IMPM_COMMIT}\"\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)  # an unchanged header keeps its time stamp: nothing recompiles
  file(WRITE "${OUTPUT}" "${text}")
endif()
