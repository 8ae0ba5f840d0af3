# needle_add_spirv(TARGET SOURCES... INCLUDES...): GLSL -> SPIR-V at build time, embedded as
# uint32_t arrays (spirv/<name>_<stage>.h holding <name>_<stage>_spv[]) in an INTERFACE library
# TARGET whose include folder holds spirv/. A compile error, or an output glslang could not
# write, fails the build; editing a source or an include rebuilds. Works with every generator:
# the output folder is made at configure time (Make, unlike Ninja, does not make it).
set(NEEDLE_COMPILE_SHADER_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/compile_shader.cmake)

function(needle_add_spirv target)
  cmake_parse_arguments(arg "" "" "SOURCES;INCLUDES" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${out_dir})
  set(headers)
  foreach(src ${arg_SOURCES})
    get_filename_component(file_name ${src} NAME)
    string(REPLACE "." "_" var ${file_name})
    set(out ${out_dir}/${var}.h)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${CMAKE_COMMAND} -DGLSLANG=${GLSLANG_VALIDATOR} -DSRC=${src} -DOUT=${out} -DVAR=${var}
              -P ${NEEDLE_COMPILE_SHADER_SCRIPT}
      DEPENDS ${src} ${arg_INCLUDES} ${NEEDLE_COMPILE_SHADER_SCRIPT}
      COMMENT "glslang ${file_name}"
      VERBATIM)
    list(APPEND headers ${out})
  endforeach()
  add_custom_target(${target}_spirv DEPENDS ${headers})
  add_library(${target} INTERFACE)
  target_include_directories(${target} INTERFACE ${CMAKE_CURRENT_BINARY_DIR})
  add_dependencies(${target} ${target}_spirv)
endfunction()
