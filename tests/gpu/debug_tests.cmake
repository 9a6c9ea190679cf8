# The debugging workflow (docs/debugging.md), included from tests/gpu/CMakeLists.txt.
#
# Planted bugs: the debug variant of the compute shader compiled with one deliberate bug each
# (TP_BUG_* in shaders/trace_bvh.glsl and common/shared/), as .spv files that the renderer loads
# in place of its own debug module through TWINPATH_DEBUG_SPIRV.
set(BUG_SPIRV_DIR ${CMAKE_CURRENT_BINARY_DIR}/bug_spirv)
set(BUG_SPIRV)
foreach(bug FRESNEL_SIGN SWAP_BARY LIGHT_PDF RNG_DIM)
  add_custom_command(
    OUTPUT ${BUG_SPIRV_DIR}/${bug}.spv
    COMMAND ${CMAKE_COMMAND} -E make_directory ${BUG_SPIRV_DIR}
    COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 -I${PROJECT_SOURCE_DIR}/shaders
            -I${PROJECT_SOURCE_DIR}/common -DTP_DEBUG_SHADER -DTP_BUG_${bug}
            --depfile ${BUG_SPIRV_DIR}/${bug}.spv.d -o ${BUG_SPIRV_DIR}/${bug}.spv
            ${PROJECT_SOURCE_DIR}/shaders/render_compute.comp
    DEPENDS ${PROJECT_SOURCE_DIR}/shaders/render_compute.comp
    DEPFILE ${BUG_SPIRV_DIR}/${bug}.spv.d
    COMMENT "Compiling render_compute.comp with the planted bug ${bug}"
    VERBATIM)
  list(APPEND BUG_SPIRV ${BUG_SPIRV_DIR}/${bug}.spv)
endforeach()
add_custom_target(gpu_bug_shaders DEPENDS ${BUG_SPIRV})

twinpath_gpu_test(gpu_debug_workflow_test SOURCES debug_workflow_test.cpp
  LIBS nlohmann_json::nlohmann_json)
add_dependencies(gpu_debug_workflow_test gpu_bug_shaders)
target_compile_definitions(gpu_debug_workflow_test PRIVATE TP_BUG_SPIRV_DIR="${BUG_SPIRV_DIR}")

# The debug variants of the render stages (pipeline mode's cannot run on lavapipe) must pass
# spirv-val like the normal ones.
foreach(shader render_compute.comp render_pipeline.rgen)
  add_test(NAME spirv_val_${shader}_debug
    COMMAND ${CMAKE_COMMAND} -DGLSLANG=${GLSLANG_VALIDATOR} -DSPIRV_VAL=${SPIRV_VAL}
            -DSOURCE=${PROJECT_SOURCE_DIR}/shaders/${shader} -DDEFINES=TP_DEBUG_SHADER
            -DINCLUDES=${PROJECT_SOURCE_DIR}/shaders$<SEMICOLON>${PROJECT_SOURCE_DIR}/common
            -DOUTPUT=${CMAKE_CURRENT_BINARY_DIR}/spirv_val/${shader}.debug.spv
            -P ${CMAKE_CURRENT_SOURCE_DIR}/spirv_val.cmake)
  set_tests_properties(spirv_val_${shader}_debug PROPERTIES LABELS gpu
                       SKIP_REGULAR_EXPRESSION "spirv-val not found")
endforeach()
