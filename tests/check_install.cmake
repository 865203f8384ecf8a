# The installed package, as a user outside the checkout sees it: installs the build into a fresh
# prefix in a temporary folder outside the checkout, and from there
# - builds tests/consumer against it with find_package(sweetspot REQUIRED), runs one impact and
#   checks its v_f against the installed `sweetspot impact --bat r161 --json`, bit for bit (both
#   print 17 significant digits): the program finds the shipped bat by name;
# - builds and runs the documentation's example, docs/examples/cpp, copied there (its bat from
#   sweetspot_DATA_DIR): its exit speed is the program's (both print 6 digits);
# - runs a shipped study from share/sweetspot/studies (its bats/... paths lead to the shipped bats);
# - with PYTHON given, imports the installed Python module, loads the shipped bat by name and runs a
#   study through run_study, which finds the installed program with none on PATH.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... [-DPYTHON=... -DPYTHON_INSTALL_DIR=...] -P check_install.cmake
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${work} RESULT_VARIABLE failed OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(failed)
    message(FATAL_ERROR "failed (${failed}): ${ARGN}\n${out}\n${err}\n(left in ${work})")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
function(fail message)
  message(FATAL_ERROR "${message}\n(left in ${work})")
endfunction()

set(tmp $ENV{TMPDIR})
if(NOT tmp)
  set(tmp /tmp)
endif()
string(RANDOM LENGTH 8 suffix)
set(work ${tmp}/sweetspot-install-${suffix})
cmake_path(IS_PREFIX SOURCE_DIR ${work} NORMALIZE inside)
if(inside)
  message(FATAL_ERROR "${work} lies inside the checkout ${SOURCE_DIR}: set TMPDIR to a folder outside it")
endif()
file(MAKE_DIRECTORY ${work})
set(prefix ${work}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(file include/sweetspot/impact/impact.hpp include/sweetspot/study/study.hpp bin/sweetspot
        lib/cmake/sweetspot/sweetspotConfig.cmake lib/cmake/sweetspot/sweetspotConfigVersion.cmake
        share/sweetspot/bats/r161.toml share/sweetspot/bats/r161_profile.csv share/sweetspot/studies/design_space.toml
        share/sweetspot/studies/bats/torpedo.toml share/doc/sweetspot/LICENSE share/doc/sweetspot/CITATION.cff)
  if(NOT EXISTS ${prefix}/${file})
    fail("not installed: ${prefix}/${file}")
  endif()
endforeach()
set(program ${prefix}/bin/sweetspot)

# Only the install prefix is searched for sweetspot: not the build tree, nor its package registry.
set(find_installed -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${work}/consumer ${find_installed})
run(${CMAKE_COMMAND} --build ${work}/consumer)
set(scene 0.7 40 10 40)  # z, ball speed, CM speed, omega
run(${work}/consumer/consumer ${prefix}/share/sweetspot/bats/r161.toml ${scene})
string(STRIP "${out}" consumer_vf)
list(GET scene 0 z)
list(GET scene 1 ball_speed)
list(GET scene 2 cm_speed)
list(GET scene 3 omega)
set(impact impact --bat r161 --z ${z} --ball-speed ${ball_speed} --cm-speed ${cm_speed} --omega ${omega})
run(${program} ${impact} --json)
string(JSON program_vf GET "${out}" vf)  # the number as the program wrote it (%.17g)
if(NOT consumer_vf STREQUAL program_vf)
  fail("v_f differs: consumer ${consumer_vf}, sweetspot impact ${program_vf}")
endif()
message(STATUS "v_f ${consumer_vf} from the installed library and from the installed sweetspot impact --bat r161")

# The documentation's example, as a reader copies it.
file(COPY ${SOURCE_DIR}/docs/examples/cpp/CMakeLists.txt ${SOURCE_DIR}/docs/examples/cpp/main.cpp
     DESTINATION ${work}/example)
run(${CMAKE_COMMAND} -S ${work}/example -B ${work}/example/build ${find_installed})
run(${CMAKE_COMMAND} --build ${work}/example/build)
run(${work}/example/build/exit_speed)
string(STRIP "${out}" example)
run(${program} ${impact})
string(REGEX MATCH "exit speed vf +([^ ]+) m/s" found "${out}")
if(NOT example STREQUAL "R161: exit speed ${CMAKE_MATCH_1} m/s at z = ${z} m")
  fail("docs/examples/cpp printed '${example}'; sweetspot impact gives vf ${CMAKE_MATCH_1} m/s")
endif()
message(STATUS "docs/examples/cpp: ${example}")

# A shipped study, run where it is installed.
run(${program} run ${prefix}/share/sweetspot/studies/high_impact.toml -o ${work}/high_impact.h5 --quiet)
if(NOT EXISTS ${work}/high_impact.h5)
  fail("the installed study high_impact.toml wrote no dataset")
endif()

if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_INSTALL_DIR})
  # (Lines, not ';': a ';' would split the argument as a CMake list.)
  run(${PYTHON} -c "import sweetspot\nprint(sweetspot.__file__)\nprint(sweetspot.Bat.load('r161').name)")
  string(FIND "${out}" "${prefix}/" at)
  if(NOT at EQUAL 0 OR NOT out MATCHES "\nR161\n$")
    fail("the installed Python module, from ${prefix}: ${out}")
  endif()
  message(STATUS "the installed Python module loads the shipped bat r161")
  # run_study runs the program installed beside the module, with no sweetspot on PATH (it looked
  # only in the build tree's layout, then on PATH).
  set(ENV{PATH} /usr/bin:/bin)
  string(CONCAT code "import sweetspot\nprint(sweetspot._program())\n"
         "print(sweetspot.run_study('${prefix}/share/sweetspot/studies/toy.toml').vf.size)")
  run(${PYTHON} -c "${code}")
  file(REAL_PATH ${program} installed)
  if(NOT out MATCHES "^${installed}\n[1-9][0-9]*\n$")
    fail("run_study from the installed module, PATH without sweetspot: ${out} (expected ${installed})")
  endif()
  message(STATUS "the installed module's run_study runs the installed program")
endif()
file(REMOVE_RECURSE ${work})
