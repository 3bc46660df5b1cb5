# One custom command per shader: glslangValidator (Vulkan 1.3) with a depfile
# for the headers it includes, then spirv-val. The fresh modules land in
# ${CMAKE_BINARY_DIR}/spirv and are embedded into the library; the committed
# copies in spirv/ must match them byte for byte (tests/spirv_fresh_test).
# `cmake --build build --target update_spirv` refreshes the committed copies.

set(TIDEPOOL_SHADER_DIR ${CMAKE_SOURCE_DIR}/shaders_glsl)
set(TIDEPOOL_SPIRV_DIR ${CMAKE_BINARY_DIR}/spirv)
set(TIDEPOOL_COMMITTED_SPIRV_DIR ${CMAKE_SOURCE_DIR}/spirv)

# Sources compiled again with macros defined, as SOURCE:MACROS:VARIANT
# (MACROS joined by '+'; the variant's module is VARIANT.spv). The opaque
# surfaces' colour-only variants leave out the G-buffer outputs, for frames
# without AO: outputs with no attachment behind them draw, but the
# validation layer warns of each. The no-shadows variants leave out the sun
# shadows' code, for scenes with nothing to cast one: on lavapipe the code
# costs where it never runs (docs/sun-shadows.md). The scattering variants
# hold the light scattered in the water, for scenes whose water scatters
# (docs/light-in-the-water.md); the ground is never under the water.
set(TIDEPOOL_SHADER_VARIANTS "")
foreach(surface ground pool_walls pool_floor sphere box)
  list(APPEND TIDEPOOL_SHADER_VARIANTS
    ${surface}.frag:TP_COLOR_ONLY:${surface}.color_only.frag
    ${surface}.frag:TP_NO_SHADOWS:${surface}.no_shadows.frag
    ${surface}.frag:TP_COLOR_ONLY+TP_NO_SHADOWS:${surface}.color_only.no_shadows.frag)
endforeach()
foreach(surface pool_walls pool_floor sphere box)
  list(APPEND TIDEPOOL_SHADER_VARIANTS
    ${surface}.frag:TP_SCATTERING:${surface}.scattering.frag
    ${surface}.frag:TP_COLOR_ONLY+TP_SCATTERING:${surface}.color_only.scattering.frag
    ${surface}.frag:TP_NO_SHADOWS+TP_SCATTERING:${surface}.no_shadows.scattering.frag
    ${surface}.frag:TP_COLOR_ONLY+TP_NO_SHADOWS+TP_SCATTERING:${surface}.color_only.no_shadows.scattering.frag)
endforeach()
foreach(water water_surface.frag water_surface_deferred.comp water_surface_apparent.frag water_surface_below.frag
        glass.frag)
  string(REGEX REPLACE "\\.[a-z]+$" "" name ${water})
  string(REGEX MATCH "[a-z]+$" stage ${water})
  list(APPEND TIDEPOOL_SHADER_VARIANTS
    ${water}:TP_NO_SHADOWS:${name}.no_shadows.${stage}
    ${water}:TP_SCATTERING:${name}.scattering.${stage}
    ${water}:TP_NO_SHADOWS+TP_SCATTERING:${name}.no_shadows.scattering.${stage})
endforeach()
# Each water shader with `macro` (its modules named `suffix`), alone and
# with the shadows left out, the scattering, and both.
function(tidepool_water_variants macro suffix)
  foreach(water ${ARGN})
    string(REGEX REPLACE "\\.[a-z]+$" "" name ${water})
    string(REGEX MATCH "[a-z]+$" stage ${water})
    list(APPEND TIDEPOOL_SHADER_VARIANTS
      ${water}:${macro}:${name}.${suffix}.${stage}
      ${water}:TP_NO_SHADOWS+${macro}:${name}.no_shadows.${suffix}.${stage}
      ${water}:TP_SCATTERING+${macro}:${name}.scattering.${suffix}.${stage}
      ${water}:TP_NO_SHADOWS+TP_SCATTERING+${macro}:${name}.no_shadows.scattering.${suffix}.${stage})
  endforeach()
  set(TIDEPOOL_SHADER_VARIANTS ${TIDEPOOL_SHADER_VARIANTS} PARENT_SCOPE)
endfunction()
# The water's rays meeting glass (lib/scene_rays.glsl's backdrop), for
# scenes with glass spheres or boxes: the casts they add cost compile time.
tidepool_water_variants(TP_GLASS glass water_surface.frag water_surface_deferred.comp water_surface_apparent.frag
                        water_surface_below.frag)
# The glass pass's draw of glass boxes (render/glass.cpp): the exact path
# through a box in place of the sphere's image-space search.
tidepool_water_variants(TP_GLASS_BOX box glass.frag)
# The water's passes that write zero into the G-buffer's ambient image where
# the water is seen, for frames whose resolve pass takes AO after the water
# (render/frame_resolve.hpp); never with glass, whose frames apply AO before it.
tidepool_water_variants(TP_CLEAR_AMBIENT clear_ambient water_surface_deferred.comp water_surface_below.frag)
# The resolve pass with the AO taken in it, at full and at half resolution.
list(APPEND TIDEPOOL_SHADER_VARIANTS resolve.comp:TP_AO:resolve.ao.comp resolve.comp:TP_AO+TP_AO_UPSAMPLE:resolve.ao_upsample.comp)
# The resolve over listed tiles (render/frame_resolve.hpp), each of the three.
list(APPEND TIDEPOOL_SHADER_VARIANTS resolve.comp:TP_LISTED_TILES:resolve.listed.comp
     resolve.comp:TP_AO+TP_LISTED_TILES:resolve.ao.listed.comp
     resolve.comp:TP_AO+TP_AO_UPSAMPLE+TP_LISTED_TILES:resolve.ao_upsample.listed.comp)

# The AO's apply pass that upsamples half-resolution AO as it applies it.
list(APPEND TIDEPOOL_SHADER_VARIANTS ao_apply.comp:TP_UPSAMPLE:ao_apply.upsample.comp)
# The floor's depth and normal alone (render/pool.cpp), without the G-buffer for frames without AO.
list(APPEND TIDEPOOL_SHADER_VARIANTS pool_floor_depth.frag:TP_COLOR_ONLY:pool_floor_depth.color_only.frag)
# The sky behind the ground (render/sky.cpp), without the G-buffer for frames without AO.
list(APPEND TIDEPOOL_SHADER_VARIANTS sky_background.frag:TP_COLOR_ONLY:sky_background.color_only.frag)

function(tidepool_compile_shaders)
  file(GLOB shader_sources CONFIGURE_DEPENDS
    ${TIDEPOOL_SHADER_DIR}/*.comp ${TIDEPOOL_SHADER_DIR}/*.vert ${TIDEPOOL_SHADER_DIR}/*.frag)
  file(MAKE_DIRECTORY ${TIDEPOOL_SPIRV_DIR})
  set(outputs "")
  set(copies "")
  set(builds "")
  foreach(src ${shader_sources})
    get_filename_component(name ${src} NAME)
    list(APPEND builds "${name}::${name}")
  endforeach()
  list(APPEND builds ${TIDEPOOL_SHADER_VARIANTS})
  foreach(build ${builds})
    string(REPLACE ":" ";" parts "${build}")
    list(GET parts 0 source_name)
    list(GET parts 1 macro)
    list(GET parts 2 name)
    set(src ${TIDEPOOL_SHADER_DIR}/${source_name})
    set(defines "")
    if(macro)
      string(REPLACE "+" ";" macros "${macro}")
      foreach(m ${macros})
        list(APPEND defines -D${m})
      endforeach()
    endif()
    set(out ${TIDEPOOL_SPIRV_DIR}/${name}.spv)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.3 -I${TIDEPOOL_SHADER_DIR} ${defines}
              --depfile ${out}.d -o ${out} ${src}
      COMMAND ${SPIRV_VAL} --target-env vulkan1.3 ${out}
      MAIN_DEPENDENCY ${src}
      DEPFILE ${out}.d
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND outputs ${out})
    list(APPEND copies COMMAND ${CMAKE_COMMAND} -E copy_if_different ${out} ${TIDEPOOL_COMMITTED_SPIRV_DIR}/${name}.spv)
  endforeach()

  set(embedded ${CMAKE_BINARY_DIR}/generated/spirv_embedded.cpp)
  # '|' for ';': a list does not survive a custom command's arguments whole.
  string(REPLACE ";" "|" variants_arg "${TIDEPOOL_SHADER_VARIANTS}")
  add_custom_command(
    OUTPUT ${embedded}
    COMMAND ${CMAKE_COMMAND} -DSPIRV_DIR=${TIDEPOOL_SPIRV_DIR} -DOUT=${embedded}
            -DVARIANTS=${variants_arg}
            -P ${CMAKE_SOURCE_DIR}/cmake/embed_spirv.cmake
    DEPENDS ${outputs} ${CMAKE_SOURCE_DIR}/cmake/embed_spirv.cmake
    COMMENT "Embedding SPIR-V"
    VERBATIM)
  set(TIDEPOOL_SPIRV_CPP ${embedded} PARENT_SCOPE)

  # The `spirv` target owns every shader command. Targets that use the
  # outputs depend on it, so that no two targets run one command at once
  # (with make -j both would write the same .spv and race).
  add_custom_target(spirv DEPENDS ${outputs} ${embedded})
  add_custom_target(update_spirv ${copies}
    COMMENT "Copying fresh SPIR-V into spirv/")
  add_dependencies(update_spirv spirv)
endfunction()
