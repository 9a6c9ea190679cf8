# Included by spirv_val.cmake and spirv_val_spec.cmake: compiles SOURCE into OUTPUT as the build
# does (shaders/spirv.cmake: Vulkan 1.2), with INCLUDES as -I and DEFINES as -D.
include(${CMAKE_CURRENT_LIST_DIR}/../../shaders/glslang_flags.cmake)
tp_glslang_flags(include_flags INCLUDES ${INCLUDES} DEFINES ${DEFINES})
get_filename_component(out_dir ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${out_dir})
execute_process(
  COMMAND ${GLSLANG} --quiet --target-env vulkan1.2 ${include_flags} -o ${OUTPUT} ${SOURCE}
  RESULT_VARIABLE compiled)
if(NOT compiled EQUAL 0)
  message(FATAL_ERROR "glslangValidator failed on ${SOURCE}")
endif()
