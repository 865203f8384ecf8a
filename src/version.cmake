# Writes version.hpp (from version.hpp.in) with the commit the sources are at, marked "-dirty"
# when the tree differs from that commit (changed, staged or untracked files that .gitignore does
# not hide). Run by the build on every build, not only at configure time, so the mark is never
# that of an earlier state of the tree; configure_file rewrites the header only when its text
# changes, so an unchanged tree recompiles nothing.
#   cmake -DSOURCE_DIR=... -DINPUT=version.hpp.in -DOUTPUT=.../version.hpp -DPROJECT_VERSION=x.y.z -P version.cmake
execute_process(COMMAND git rev-parse --short HEAD
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE SWEETSPOT_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE failed ERROR_QUIET)
if(failed OR NOT SWEETSPOT_GIT_COMMIT)
  set(SWEETSPOT_GIT_COMMIT unknown)  # not a git checkout (a tarball), or no git
else()
  execute_process(COMMAND git status --porcelain --untracked-files=normal
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE changes RESULT_VARIABLE failed ERROR_QUIET)
  if(failed OR NOT changes STREQUAL "")
    string(APPEND SWEETSPOT_GIT_COMMIT -dirty)  # a tree git cannot vouch for is not clean either
  endif()
endif()
configure_file(${INPUT} ${OUTPUT} @ONLY)
