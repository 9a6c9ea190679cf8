# tp_embed_spirv(OUTPUT <header> SOURCE <shader> NAME <identifier> [INCLUDES <dir>...]
#                [DEFINES <NAME[=value]>...])
#
# Compiles a GLSL shader with glslangValidator for Vulkan 1.2 into a C header that holds the
# SPIR-V words as `const uint32_t NAME[]`. glslang's --depfile lists every file the shader
# included, so editing any of them (common/shared/*.h too) rebuilds the header and whatever
# embeds it. shaders/ and common/ are always on the include path.
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
include(${CMAKE_CURRENT_LIST_DIR}/glslang_flags.cmake)

function(tp_embed_spirv)
  cmake_parse_arguments(S "" "OUTPUT;SOURCE;NAME" "INCLUDES;DEFINES" ${ARGN})
  tp_glslang_flags(includes INCLUDES ${PROJECT_SOURCE_DIR}/shaders ${PROJECT_SOURCE_DIR}/common
                   ${S_INCLUDES} DEFINES ${S_DEFINES})
  get_filename_component(out_dir ${S_OUTPUT} DIRECTORY)
  add_custom_command(
    OUTPUT ${S_OUTPUT}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
    COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 ${includes} --vn ${S_NAME}
            --depfile ${S_OUTPUT}.d -o ${S_OUTPUT} ${S_SOURCE}
    DEPENDS ${S_SOURCE}
    DEPFILE ${S_OUTPUT}.d
    COMMENT "Compiling ${S_SOURCE} to SPIR-V"
    VERBATIM)
endfunction()
