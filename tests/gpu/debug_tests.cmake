# The debugging workflow (docs/debugging.md), included from tests/gpu/CMakeLists.txt.
#
# Planted bugs: the debug variant of the compute shader compiled from a copy of the sources with
# one deliberate bug each (plant_bug.cmake replaces the text FROM by TO in FILE), as .spv files
# that the renderer loads in place of its own debug module through TWINPATH_DEBUG_SPIRV.
set(BUG_SPIRV_DIR ${CMAKE_CURRENT_BINARY_DIR}/bug_spirv)
set(BUG_SPIRV)
set(BUG_FRESNEL_SIGN common/shared/brdf.h
    "float r_parl = (eta * cos_i - cos_t)" "float r_parl = (eta * cos_i + cos_t)")
set(BUG_SWAP_BARY shaders/bvh_triangles.glsl
    "hit.bary = vec2(tuv.y, tuv.z)" "hit.bary = vec2(tuv.z, tuv.y)")
set(BUG_LIGHT_PDF common/shared/lights.h
    "return dist * dist / (cos_light * area)" "return 2.0f * dist * dist / (cos_light * area)")
set(BUG_RNG_DIM common/shared/integrator.h
    "vec2 dir_uv = rng_bounce2(st.key, st.bounce, RNG_DIR_U)"
    "vec2 dir_uv = rng_bounce2(st.key, st.bounce, RNG_DIR_U).xx")
file(GLOB_RECURSE BUG_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/*
     ${PROJECT_SOURCE_DIR}/common/shared/*)
foreach(bug FRESNEL_SIGN SWAP_BARY LIGHT_PDF RNG_DIM)
  list(GET BUG_${bug} 0 file)
  list(GET BUG_${bug} 1 from)
  list(GET BUG_${bug} 2 to)
  set(copy ${BUG_SPIRV_DIR}/${bug}_src)
  add_custom_command(
    OUTPUT ${BUG_SPIRV_DIR}/${bug}.spv
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} -DCOPY_DIR=${copy} -DFILE=${file}
            -DFROM=${from} -DTO=${to} -P ${CMAKE_CURRENT_SOURCE_DIR}/plant_bug.cmake
    COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 -I${copy}/shaders
            -I${copy}/common -DTP_DEBUG_SHADER -o ${BUG_SPIRV_DIR}/${bug}.spv
            ${copy}/shaders/render_compute.comp
    DEPENDS ${BUG_SOURCES} ${CMAKE_CURRENT_SOURCE_DIR}/plant_bug.cmake
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

# twinpath verify (docs/debugging.md, "verify"): the same planted bugs, found and named by one
# command with its defaults; the unmodified shader consistent; the report's commands.
twinpath_gpu_test(gpu_verify_test SOURCES verify_cli_test.cpp LIBS nlohmann_json::nlohmann_json)
add_dependencies(gpu_verify_test gpu_bug_shaders)
target_compile_definitions(gpu_verify_test PRIVATE TP_BUG_SPIRV_DIR="${BUG_SPIRV_DIR}")

# docs/debugging.md's worked example is the output of scripts/debugging_example.sh on lavapipe:
# the doc must match a run of the commands it shows.
add_test(NAME debugging_example_up_to_date
  COMMAND ${PROJECT_SOURCE_DIR}/scripts/debugging_example.sh --check $<TARGET_FILE:twinpath>
          ${BUG_SPIRV_DIR})
set_tests_properties(debugging_example_up_to_date PROPERTIES LABELS gpu)
