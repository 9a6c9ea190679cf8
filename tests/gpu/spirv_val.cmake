# cmake -DGLSLANG=... -DSPIRV_VAL=... -DSOURCE=shader -DINCLUDES="dir;dir" -DOUTPUT=x.spv -P
# Compiles SOURCE as the build does (shaders/spirv.cmake: Vulkan 1.2) and validates the module
# with spirv-val under the rules of that environment. Without spirv-val (Debian: spirv-tools)
# it says so, which CTest reports as a skipped test (SKIP_REGULAR_EXPRESSION).
if(NOT SPIRV_VAL)
  message("spirv-val not found (Debian: spirv-tools): skipped")
  return()
endif()
set(include_flags)
foreach(dir IN LISTS INCLUDES)
  list(APPEND include_flags -I${dir})
endforeach()
foreach(def IN LISTS DEFINES)
  list(APPEND include_flags -D${def})
endforeach()
get_filename_component(out_dir ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${out_dir})
execute_process(
  COMMAND ${GLSLANG} --quiet --target-env vulkan1.2 ${include_flags} -o ${OUTPUT} ${SOURCE}
  RESULT_VARIABLE compiled)
if(NOT compiled EQUAL 0)
  message(FATAL_ERROR "glslangValidator failed on ${SOURCE}")
endif()
execute_process(COMMAND ${SPIRV_VAL} --target-env vulkan1.2 --scalar-block-layout ${OUTPUT}
                RESULT_VARIABLE valid)
if(NOT valid EQUAL 0)
  message(FATAL_ERROR "spirv-val rejects ${OUTPUT}")
endif()
