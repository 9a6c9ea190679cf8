# cmake -DGLSLANG=... -DSPIRV_VAL=... -DSOURCE=shader -DINCLUDES="dir;dir" -DOUTPUT=x.spv -P
# Compiles SOURCE as the build does (shaders/spirv.cmake: Vulkan 1.2) and validates the module
# with spirv-val under the rules of that environment. Without spirv-val (Debian: spirv-tools)
# it says so, which CTest reports as a skipped test (SKIP_REGULAR_EXPRESSION).
if(NOT SPIRV_VAL)
  message("spirv-val not found (Debian: spirv-tools): skipped")
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/spirv_compile.cmake)
execute_process(COMMAND ${SPIRV_VAL} --target-env vulkan1.2 --scalar-block-layout ${OUTPUT}
                RESULT_VARIABLE valid)
if(NOT valid EQUAL 0)
  message(FATAL_ERROR "spirv-val rejects ${OUTPUT}")
endif()
