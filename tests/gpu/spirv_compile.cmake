# Included by spirv_val.cmake and spirv_val_spec.cmake: compiles SOURCE into OUTPUT as the build
# does (shaders/spirv.cmake: Vulkan 1.2), with INCLUDES as -I and DEFINES as -D.
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
