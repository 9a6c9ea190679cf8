# cmake -DGLSLANG=... -DSPIRV_VAL=... -DSPIRV_OPT=... -DSOURCE=shader -DINCLUDES="dir;dir"
#       -DOUTPUT=x.spv -DFEATURES=<mask> -P
# The render shader specialized to a feature mask as a driver would see it: compiled
# as the build does, the SPEC_SCENE_FEATURES constant (id 0) set to FEATURES and frozen, then
# optimized (inlining and dead-code elimination, what drivers do with the constant); both the
# frozen and the optimized module must pass spirv-val. Prints the optimized size, a proxy for
# how much code the mask removes.
if(NOT SPIRV_VAL OR NOT SPIRV_OPT)
  message("spirv-val or spirv-opt not found (Debian: spirv-tools): skipped")
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/spirv_compile.cmake)
execute_process(
  COMMAND ${SPIRV_OPT} --target-env=vulkan1.2 --scalar-block-layout
          --set-spec-const-default-value "0:${FEATURES}" --freeze-spec-const
          ${OUTPUT} -o ${OUTPUT}.frozen.spv
  RESULT_VARIABLE frozen)
if(NOT frozen EQUAL 0)
  message(FATAL_ERROR "spirv-opt could not freeze the feature constant at ${FEATURES}")
endif()
execute_process(
  COMMAND ${SPIRV_OPT} --target-env=vulkan1.2 --scalar-block-layout -O ${OUTPUT}.frozen.spv
          -o ${OUTPUT}.opt.spv
  RESULT_VARIABLE optimized)
if(NOT optimized EQUAL 0)
  message(FATAL_ERROR "spirv-opt -O failed on the frozen module")
endif()
foreach(module ${OUTPUT}.frozen.spv ${OUTPUT}.opt.spv)
  execute_process(COMMAND ${SPIRV_VAL} --target-env vulkan1.2 --scalar-block-layout ${module}
                  RESULT_VARIABLE valid)
  if(NOT valid EQUAL 0)
    message(FATAL_ERROR "spirv-val rejects ${module}")
  endif()
endforeach()
file(SIZE ${OUTPUT}.opt.spv opt_size)
message("features ${FEATURES}: optimized module ${opt_size} bytes")
