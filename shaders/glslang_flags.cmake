# tp_glslang_flags(<out-var> [INCLUDES <dir>...] [DEFINES <NAME[=value]>...])
#
# The -I and -D arguments of glslangValidator, for the build (spirv.cmake) and for the test
# scripts that compile a shader at test time (tests/gpu/spirv_compile.cmake).
function(tp_glslang_flags out)
  cmake_parse_arguments(F "" "" "INCLUDES;DEFINES" ${ARGN})
  set(flags)
  foreach(dir IN LISTS F_INCLUDES)
    list(APPEND flags -I${dir})
  endforeach()
  foreach(def IN LISTS F_DEFINES)
    list(APPEND flags -D${def})
  endforeach()
  set(${out} ${flags} PARENT_SCOPE)
endfunction()
