# One static library per folder of src/. A library sees its own headers and
# those of the libraries it links, and no others: its include root holds one
# link, NAME -> src/NAME, so that #include "NAME/x.hpp" resolves only where
# NAME is linked. An include of a layer above fails to build.
function(tidepool_library name)
  cmake_parse_arguments(ARG "" "" "PUBLIC;PRIVATE" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${name}/*.cpp)
  add_library(tidepool_${name} STATIC ${sources})
  set(root ${CMAKE_BINARY_DIR}/include/${name})
  file(MAKE_DIRECTORY ${root})
  file(CREATE_LINK ${CMAKE_SOURCE_DIR}/src/${name} ${root}/${name} SYMBOLIC)
  target_include_directories(tidepool_${name} PUBLIC ${root})
  target_link_libraries(tidepool_${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
endfunction()

# Vulkan-Hpp's RAII header takes about 3 s of every file that includes it
# (most of those in these targets): each target compiles it once, as a
# precompiled header, and its files start from that.
function(tidepool_precompile_vulkan)
  foreach(target ${ARGN})
    target_precompile_headers(${target} PRIVATE <vulkan/vulkan_raii.hpp>)
  endforeach()
endfunction()
