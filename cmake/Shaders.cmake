# Compiles GLSL with glslc at build time into C++ headers holding the SPIR-V words
# (glslc -mfmt=num), so the binary embeds its shaders and no .spv is ever committed.
#   dvsgi_add_shaders(TARGET name SOURCES a.comp b.vert a.comp@VARIANT a.frag@A+B ...)
# creates an INTERFACE library `name` whose include directory holds
# shaders/<file>.<stage>.inc for every source (e.g. shaders/lighting.comp.inc).
# Extra definitions for every shader, for diagnostics only (scripts/cone-check.sh
# builds with DVSGI_SINGLE_CONE=k); empty in every normal build.
set(DVSGI_SHADER_DEFINES "" CACHE STRING "extra NAME=VALUE definitions for every shader (diagnostics)")

function(dvsgi_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(defines)
  foreach(def ${DVSGI_SHADER_DEFINES})
    list(APPEND defines -D${def})
  endforeach()
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/include/shaders)
  file(MAKE_DIRECTORY ${out_dir})
  set(outputs)
  foreach(entry ${ARG_SOURCES})
    # "file.comp@VARIANT": file.comp again, with DVSGI_VARIANT defined, as file_variant.comp.inc;
    # "file.frag@A+B" defines DVSGI_A and DVSGI_B, as file_a_b.frag.inc.
    set(variant_defines)
    if(entry MATCHES "^(.+)@(.+)$")
      set(src ${CMAKE_MATCH_1})
      set(variant ${CMAKE_MATCH_2})
      string(REPLACE "+" ";" variant_list ${variant})
      string(REPLACE "+" "_" suffix ${variant})
      string(TOLOWER ${suffix} suffix)
      get_filename_component(base ${src} NAME_WE)
      get_filename_component(ext ${src} EXT)
      set(name ${base}_${suffix}${ext})
      foreach(v ${variant_list})
        list(APPEND variant_defines -DDVSGI_${v})
      endforeach()
    else()
      set(src ${entry})
      get_filename_component(name ${src} NAME)
    endif()
    set(abs ${CMAKE_CURRENT_SOURCE_DIR}/${src})
    set(out ${out_dir}/${name}.inc)
    set(dep ${CMAKE_CURRENT_BINARY_DIR}/${name}.d)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${GLSLC} --target-env=vulkan1.3 -O -g ${defines} ${variant_defines} -I ${CMAKE_CURRENT_SOURCE_DIR}
              -MD -MF ${dep} -mfmt=num -o ${out} ${abs}
      DEPENDS ${abs}
      DEPFILE ${dep}
      COMMENT "glslc ${name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${ARG_TARGET}_compile DEPENDS ${outputs})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_compile)
  target_include_directories(${ARG_TARGET} INTERFACE ${CMAKE_CURRENT_BINARY_DIR}/include)
endfunction()
