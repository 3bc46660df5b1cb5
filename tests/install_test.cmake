# Installs the build into a fresh prefix, then runs the installed tidepool
# from another folder: it renders, and finds its shaders beside itself.
#   cmake -DBUILD=<build dir> -DSCRATCH=<empty dir to use> -P install_test.cmake
file(REMOVE_RECURSE ${SCRATCH})
set(prefix ${SCRATCH}/prefix)
file(MAKE_DIRECTORY ${SCRATCH}/elsewhere)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix}
                RESULT_VARIABLE code OUTPUT_QUIET)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${code}")
endif()
foreach(file bin/tidepool share/tidepool/shaders_glsl/water_surface.frag share/tidepool/shaders_glsl/shared/water.h
             share/tidepool/tools/plot_bench_water.py)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "the install lacks ${file}")
  endif()
endforeach()
execute_process(COMMAND ${prefix}/bin/tidepool render --width 32 --height 18 --validate --out frame.exr
                WORKING_DIRECTORY ${SCRATCH}/elsewhere RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT EXISTS ${SCRATCH}/elsewhere/frame.exr)
  message(FATAL_ERROR "the installed tidepool did not render (exit ${code}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${prefix}/bin/tidepool view --help
                WORKING_DIRECTORY ${SCRATCH}/elsewhere RESULT_VARIABLE code OUTPUT_VARIABLE help)
string(REPLACE "\n" "" help "${help}")
string(REGEX REPLACE " +" " " help "${help}")
string(FIND "${help}" "here: ${prefix}/share/tidepool/shaders_glsl" at)
if(NOT code EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR "the installed tidepool does not take its shaders from ${prefix}/share/tidepool:\n${help}")
endif()
file(REMOVE_RECURSE ${SCRATCH})
message(STATUS "installed tidepool rendered from another folder and found its shaders beside itself")
