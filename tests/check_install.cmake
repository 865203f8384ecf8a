# The installed package, as a project outside this tree sees it: installs the build into a fresh
# prefix, configures and builds tests/consumer against it with find_package(sweetspot REQUIRED),
# runs one impact with it and checks its v_f against `sweetspot impact --json` on the same scene,
# bit for bit (both print 17 significant digits).
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DPROGRAM=... -DWORK_DIR=... -P check_install.cmake
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(failed)
    message(FATAL_ERROR "failed (${failed}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(file include/sweetspot/impact/impact.hpp include/sweetspot/study/study.hpp bin/sweetspot
        lib/cmake/sweetspot/sweetspotConfig.cmake lib/cmake/sweetspot/sweetspotConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${prefix}/${file}")
  endif()
endforeach()

# Only the install prefix is searched for sweetspot: not this build tree, nor its package registry.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)

set(bat ${SOURCE_DIR}/studies/bats/r161.toml)
set(scene 0.7 40 10 40)  # z, ball speed, CM speed, omega
run(${WORK_DIR}/build/consumer ${bat} ${scene})
string(STRIP "${out}" consumer_vf)
list(GET scene 0 z)
list(GET scene 1 ball_speed)
list(GET scene 2 cm_speed)
list(GET scene 3 omega)
run(${PROGRAM} impact --bat ${bat} --z ${z} --ball-speed ${ball_speed} --cm-speed ${cm_speed} --omega ${omega} --json)
string(JSON program_vf GET "${out}" vf)
# string(JSON) gives the number as the program wrote it (%.17g).
if(NOT consumer_vf STREQUAL program_vf)
  message(FATAL_ERROR "v_f differs: consumer ${consumer_vf}, sweetspot impact ${program_vf}")
endif()
message(STATUS "v_f ${consumer_vf} from the installed library and from sweetspot impact")
file(REMOVE_RECURSE ${WORK_DIR})
