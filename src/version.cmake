# Writes version.hpp (from version.hpp.in) with the commit the sources are at, marked "-dirty"
# when the tree differs from that commit (changed, staged or untracked files that .gitignore does
# not hide). Run by the build on every build, not only at configure time, so the mark is never
# that of an earlier state of the tree; configure_file rewrites the header only when its text
# changes, so an unchanged tree recompiles nothing.
# Only a checkout whose top is SOURCE_DIR counts: sources unpacked inside another repository are
# not that repository's commit. Without a checkout (a tarball), the commit is the one `git archive`
# wrote into cmake/git_archival.txt (export-subst, cmake/.gitattributes), else "unknown".
#   cmake -DSOURCE_DIR=... -DINPUT=version.hpp.in -DOUTPUT=.../version.hpp -DPROJECT_VERSION=x.y.z -P version.cmake
execute_process(COMMAND git rev-parse --show-toplevel --short HEAD
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE lines OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE failed ERROR_QUIET)
set(SWEETSPOT_GIT_COMMIT unknown)
if(NOT failed)
  string(REPLACE "\n" ";" lines "${lines}")
  list(GET lines 0 top)
  list(GET lines 1 commit)
  file(REAL_PATH ${top} top)
  file(REAL_PATH ${SOURCE_DIR} source)
endif()
if(NOT failed AND top STREQUAL source)
  set(SWEETSPOT_GIT_COMMIT ${commit})
  execute_process(COMMAND git status --porcelain --untracked-files=normal
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
  if(failed OR NOT changes STREQUAL "")
    string(APPEND SWEETSPOT_GIT_COMMIT -dirty)  # a tree git cannot vouch for is not clean either
  endif()
elseif(EXISTS ${SOURCE_DIR}/cmake/git_archival.txt)
  file(STRINGS ${SOURCE_DIR}/cmake/git_archival.txt archived REGEX "^commit: [0-9a-f]+$")
  if(archived)
    string(REPLACE "commit: " "" SWEETSPOT_GIT_COMMIT "${archived}")
  endif()
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
