# Compiles one GLSL source to an embedded SPIR-V header: cmake -DGLSLANG=... -DSRC=... -DOUT=...
# -DVAR=... -P compile_shader.cmake. glslangValidator exits 0 when it cannot write its output
# ("ERROR: Failed to open file"), so success here means: exit status 0 and the output written.
# It writes to a temporary name first, so an interrupted or failed compile leaves no header.
foreach(arg GLSLANG SRC OUT VAR)
  if(NOT DEFINED ${arg})
    message(FATAL_ERROR "compile_shader.cmake: -D${arg}=... is required")
  endif()
endforeach()

set(tmp "${OUT}.tmp")
file(REMOVE "${tmp}")
execute_process(
  COMMAND "${GLSLANG}" -V --target-env vulkan1.1 --quiet --vn "${VAR}_spv" -o "${tmp}" "${SRC}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  file(REMOVE "${tmp}")
  message(FATAL_ERROR "glslang failed on ${SRC} (exit ${result}):\n${output}")
endif()
if(NOT EXISTS "${tmp}" OR IS_DIRECTORY "${tmp}")
  message(FATAL_ERROR "glslang wrote no output for ${SRC} (to ${tmp}):\n${output}")
endif()
file(RENAME "${tmp}" "${OUT}")
