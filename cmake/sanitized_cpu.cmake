# The sanitized CPU build (TIDEPOOL_FUZZ, with clang++): the scene, sim and io
# code the CPU-side tests use, built with AddressSanitizer and
# UndefinedBehaviorSanitizer (and libFuzzer's coverage), the CPU-side test
# suites run under them, and the two libFuzzer targets, each run for a
# bounded time by ctest from a seed corpus. A build of its own, beside the
# main one (tools/test.sh makes both):
#   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DTIDEPOOL_FUZZ=ON
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "TIDEPOOL_FUZZ needs clang++ (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
endif()
set(TIDEPOOL_FUZZ_SECONDS 30 CACHE STRING "How long ctest runs each fuzz target")
set(sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
# The instrumentation keeps the vectorizer from the OpenMP simd loops: not a finding.
add_compile_options(-Wno-pass-failed)

add_library(tidepool_cpu STATIC
  src/scene/scene.cpp src/scene/scene_file.cpp src/scene/camera.cpp
  src/base/text_file.cpp src/base/atomic_file.cpp src/base/background_work.cpp src/base/median.cpp src/base/number_text.cpp src/base/closest_word.cpp
  src/io/image_io.cpp
  src/sim/water_state.cpp src/io/water_state_file.cpp src/sim/water_params.cpp src/sim/cpu_stepper.cpp src/sim/reference_sim.cpp
  src/sim/exact_mode.cpp src/sim/wake_measures.cpp
  src/viewer/camera_controller.cpp src/viewer/water_pick.cpp src/viewer/resolution_governor.cpp
  src/cli/frame_sequence.cpp)
target_include_directories(tidepool_cpu PUBLIC src shaders_glsl)
target_compile_definitions(tidepool_cpu PUBLIC GLM_FORCE_DEPTH_ZERO_TO_ONE GLM_FORCE_RADIANS)
target_compile_options(tidepool_cpu PUBLIC ${sanitizers} -fsanitize=fuzzer-no-link)
target_link_options(tidepool_cpu PUBLIC ${sanitizers})
target_link_libraries(tidepool_cpu PUBLIC PkgConfig::OIIO glm::glm nlohmann_json::nlohmann_json OpenMP::OpenMP_CXX
                      Threads::Threads)

enable_testing()
foreach(target scene_parser state_exr)
  add_executable(fuzz_${target} tests/fuzz/${target}_fuzz.cpp)
  target_link_libraries(fuzz_${target} PRIVATE tidepool_cpu)
  target_link_options(fuzz_${target} PRIVATE -fsanitize=fuzzer)
endforeach()
# Seeds: every example scene, and the water states under tests/fuzz/seeds
# (state.exr: an 8x8 state as `sim` writes it). New inputs libFuzzer finds
# go to the build's copy of the corpus, never into the source tree.
file(GLOB scene_seeds ${CMAKE_SOURCE_DIR}/scenes/*.json)
file(COPY ${scene_seeds} DESTINATION ${CMAKE_BINARY_DIR}/corpus/scene_parser)
# oversized-attribute.exr is the fuzzer's first finding, kept as a seed: 558
# bytes whose header declares a 1.8 GB string attribute, which Debian 12's
# OpenEXR allocates before it finds the file short (the reader then fails
# cleanly). The limits below let that allocation through and would still
# stop a run that keeps growing. wide-scanlines.exr is the second: a header
# of 3,211,272 x 8 pixels, for which OpenImageIO asked 6.5 GB; readImage now
# refuses sizes beyond its limits before reading.
file(GLOB state_seeds ${CMAKE_SOURCE_DIR}/tests/fuzz/seeds/*.exr)
file(COPY ${state_seeds} DESTINATION ${CMAKE_BINARY_DIR}/corpus/state_exr)
foreach(target scene_parser state_exr)
  add_test(NAME fuzz_${target}
           COMMAND fuzz_${target} -max_total_time=${TIDEPOOL_FUZZ_SECONDS} -rss_limit_mb=4096 -malloc_limit_mb=4096
                   -max_len=65536
                   ${CMAKE_BINARY_DIR}/corpus/${target})
endforeach()

find_package(GTest REQUIRED)
include(GoogleTest)
add_executable(tidepool_cpu_tests
  tests/scene_file_test.cpp tests/sim_cpu_test.cpp tests/camera_controller_test.cpp tests/water_pick_test.cpp
  tests/resolution_governor_test.cpp tests/background_work_test.cpp tests/sphere_column_test.cpp
  tests/wake_measures_test.cpp)
target_link_libraries(tidepool_cpu_tests PRIVATE tidepool_cpu GTest::gtest GTest::gtest_main)
target_compile_definitions(tidepool_cpu_tests PRIVATE
  TIDEPOOL_EXE="/bin/false"  # process.hpp's runner; these suites do not run the executable
  TIDEPOOL_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
gtest_discover_tests(tidepool_cpu_tests TEST_PREFIX "sanitized." DISCOVERY_TIMEOUT 60)
