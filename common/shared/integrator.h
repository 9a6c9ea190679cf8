// The path loop of both engines: unidirectional path tracing with next-event estimation,
// multiple importance sampling (Veach 1997, §9.2, power heuristic) and Russian roulette, in the
// per-vertex order of path.h, drawing the random numbers of rng.h. It is written once against
// hooks that each engine defines before including this file:
//   bool trace_closest(Ray ray, OUT(TraceHit) hit)   closest hit (t, instance, primitive, bary)
//   bool trace_occluded(Ray ray)                     any hit in (0, ray.tmax)
//   TRACE_OFFSET_SLACK                               a constant: the intersector's factor on
//                                                    the ray-offset bound (offset.h)
//   TRACE_SHADOW_AFTER_SCATTER                       a constant: true where the shadow ray is
//                                                    better traced after the scattered ray is
//                                                    made (pipeline mode: the surface point is
//                                                    then dead across that traceRayEXT)
//   scene_surface, scene_material, scene_light_selection_pdf, scene_sample_light,
//   scene_environment_radiance, scene_environment_pdf,
//   SCENE_LIGHT_NORMAL_FROM_VERTICES                 (scene_access.h)
//   params, instances[], lights[], light_table[], scene_features   (as for scene_access.h)
//   RayCounts                                        a struct with camera, extension, shadow
//   path_log_recording                               a constant: whether the path log records
//   path_log_emit(PathVertex v, uint termination)    the path-log record (path_log.h)
// GLSL picks its trace hooks by include (shaders/trace_bvh.glsl for compute mode,
// shaders/trace_rtx.glsl for traceRayEXT); C++ includes this file inside the engine's class
// template (cpu_ref/cpu_engine.h), whose members are the hooks. It includes nothing itself:
// camera.h, path.h, path_log.h, rng.h and roulette.h come first.
#ifndef TP_SHARED_INTEGRATOR_H
#define TP_SHARED_INTEGRATOR_H

// The path log's statements, compiled only where the engine records (path_log_recording is a
// constant, so the condition folds away).
#define PATH_LOG(statements)                                                                       \
    if (path_log_recording) {                                                                      \
        statements;                                                                                \
    }

// Radiance estimate of sample `sample_index` of pixel (x, y); rays are counted into `rays`.
vec3 path_radiance(uint x, uint y, uint sample_index, INOUT(RayCounts) rays) {
    RngKey key = rng_key(params.sampler_id, params.seed, y * params.camera.width + x, sample_index);

    Ray ray = camera_ray(params.camera, key, x, y);
    ++rays.camera;

    vec3 L = vec3(0.0f);
    vec3 T = vec3(1.0f);
    bool prev_specular = true; // the camera ray: emitters seen directly get full weight
    float prev_pdf = 0.0f;
    for (uint bounce = 0u;; ++bounce) {
        PathVertex rec;
        PATH_LOG(rec = path_vertex_begin(sample_index, bounce, ray));
        TraceHit hit;
        if (!trace_closest(ray, hit)) {
            if (features_environment(scene_features) && params.env_light != NO_INDEX) {
                float light_pdf =
                    scene_light_selection_pdf(params.env_light) * scene_environment_pdf(ray.dir);
                float mis = emission_mis_weight(prev_specular, prev_pdf, light_pdf);
                L += T * scene_environment_radiance(ray.dir) * mis;
                PATH_LOG(rec.emitted = T * scene_environment_radiance(ray.dir) * mis;
                         rec.mis_emission = mis);
            }
            PATH_LOG(rec.radiance = L; path_log_emit(rec, TERM_ESCAPED));
            break;
        }
        uint light_offset = instances[hit.instance].light_offset;
        SurfacePoint sp = scene_surface(hit);
        surface_snap_to_ray(sp, ray.origin, ray.dir);
        Material mat = scene_material(hit.instance, sp.uv);
        vec3 wo = -ray.dir;
        PATH_LOG(rec.event = VERTEX_HIT; rec.t = hit.t; rec.instance = hit.instance;
                 rec.primitive = hit.primitive; rec.bary = hit.bary;
                 rec.material = instances[hit.instance].material; rec.position = sp.p);

        // 1. Emission, front face only.
        float cos_emit = dot(sp.ng, wo);
        PATH_LOG(rec.cos_emit = cos_emit);
        if (feature_on(scene_features, FEATURE_EMISSIVE_TRIANGLES) && !is_black(mat.ke) &&
            cos_emit > 0.0f) {
            float light_pdf = 0.0f;
            if (light_offset != NO_INDEX) {
                uint li = light_offset + hit.primitive;
                light_pdf = scene_light_selection_pdf(li) *
                            triangle_light_pdf(lights[li].area, hit.t, cos_emit);
            }
            float mis = emission_mis_weight(prev_specular, prev_pdf, light_pdf);
            L += T * mat.ke * mis;
            PATH_LOG(rec.emitted = T * mat.ke * mis; rec.mis_emission = mis);
        }

        // 2. The maximum number of scattering events.
        PATH_LOG(rec.ng = sp.ng; rec.ns = sp.ns);
        if (bounce >= params.max_depth) {
            PATH_LOG(rec.radiance = L; path_log_emit(rec, TERM_MAX_DEPTH));
            break;
        }
        if (!feature_on(scene_features, FEATURE_DIELECTRIC) || mat.type != MATERIAL_DIELECTRIC)
            surface_face_viewer(sp, wo);
        PATH_LOG(rec.ng = sp.ng; rec.ns = sp.ns);

        // 3. Next-event estimation. Where TRACE_SHADOW_AFTER_SCATTER holds, the shadow ray waits
        // for step 4 to be drawn; its contribution still reaches L before anything else does, so
        // the sums are the same in the same order.
        bool shadow_pending = false;
        Ray shadow = ray;
        vec3 shadow_contrib = vec3(0.0f);
        if (features_sample_lights(scene_features) && !material_is_delta_in(scene_features, mat) &&
            params.light_count > 0u) {
            uvec2 pick = rng_bounce2_bits(key, bounce, RNG_LIGHT_SLOT); // slot and alias coin
            uint slot = alias_slot_from_bits(pick.x, params.light_count);
            AliasEntry e = light_table[slot];
            uint li = alias_resolve(slot, e.prob, e.alias, uint_to_unit_float(pick.y));
            float sel_pdf = scene_light_selection_pdf(li);
            vec2 u = rng_bounce2(key, bounce, RNG_LIGHT_U);
            uvec2 env = rng_bounce2_bits(key, bounce, RNG_ENV_SLOT); // pixel slot and coin
            LightSample ls = scene_sample_light(li, sp.p, u, env.x, uint_to_unit_float(env.y));
            PATH_LOG(rec.light = li; rec.light_wi = ls.wi; rec.light_pdf = sel_pdf * ls.pdf;
                     rec.mis_light = 1.0f; rec.rng[RNG_LIGHT_SLOT] = uint_to_unit_float(pick.x);
                     rec.rng[RNG_LIGHT_COIN] = uint_to_unit_float(pick.y);
                     rec.rng[RNG_LIGHT_U] = u.x; rec.rng[RNG_LIGHT_V] = u.y;
                     rec.rng[RNG_ENV_SLOT] = uint_to_unit_float(env.x);
                     rec.rng[RNG_ENV_COIN] = uint_to_unit_float(env.y));
            if (ls.pdf > 0.0f && dot(ls.wi, sp.ng) > 0.0f) {
                vec3 f = bsdf_eval_in(scene_features, mat, sp.ns, wo, ls.wi);
                PATH_LOG(rec.light_f = f);
                if (!is_black(f) && !is_black(ls.radiance)) {
                    float light_pdf = sel_pdf * ls.pdf;
                    vec3 contrib = T * f * (dot(sp.ns, ls.wi) / light_pdf) * ls.radiance;
                    if (features_mis(scene_features) && !ls.delta)
                        contrib *= power_heuristic(
                            light_pdf, bsdf_pdf_in(scene_features, mat, sp.ns, wo, ls.wi));
                    PATH_LOG(rec.light_bsdf_pdf =
                                 bsdf_pdf_in(scene_features, mat, sp.ns, wo, ls.wi);
                             rec.mis_light =
                                 ls.delta ? 1.0f : power_heuristic(light_pdf, rec.light_bsdf_pdf);
                             rec.nee = contrib);
                    ++rays.shadow;
                    Ray sr = shadow_ray(sp.p, sp.p_error, sp.ng, ls, lights[li], TRACE_OFFSET_SLACK,
                                        SCENE_LIGHT_NORMAL_FROM_VERTICES);
                    if (TRACE_SHADOW_AFTER_SCATTER) {
                        shadow_pending = true;
                        shadow = sr;
                        shadow_contrib = contrib;
                    } else {
                        bool occluded = trace_occluded(sr);
                        if (!occluded) L += contrib;
                        PATH_LOG(rec.shadow = occluded ? SHADOW_OCCLUDED : SHADOW_UNOCCLUDED);
                    }
                }
            }
        }

        // 4. Scattering. The lobe choice shares a Sobol pair with the roulette (rng.h); the pair
        // is drawn only where one of them is read (the roulette's number from min_depth on), and
        // a skipped draw leaves every other number as it is (rng.h's layout is fixed).
        bool lobe_or_roulette_read = bsdf_reads_lobe_choice_in(scene_features, mat) ||
                                     bounce + 1u >= params.min_depth || path_log_recording;
        vec2 lobe_roulette =
            lobe_or_roulette_read ? rng_bounce2(key, bounce, RNG_LOBE) : vec2(0.0f);
        vec2 dir_uv = rng_bounce2(key, bounce, RNG_DIR_U);
        BsdfSample bs = bsdf_sample_in(scene_features, mat, sp.ns, wo, lobe_roulette.x, dir_uv);
        PATH_LOG(rec.rng[RNG_LOBE] = lobe_roulette.x; rec.rng[RNG_DIR_U] = dir_uv.x;
                 rec.rng[RNG_DIR_V] = dir_uv.y; rec.lobe = bs.lobe; rec.wi = bs.wi;
                 rec.bsdf_pdf = bs.pdf; rec.bsdf_weight = bs.weight; rec.radiance = L;
                 rec.throughput = T);
        bool scatter = bs.lobe != LOBE_NONE && scatter_is_consistent(sp.ng, wo, bs.wi, bs.lobe);
        Ray next = ray;
        if (TRACE_SHADOW_AFTER_SCATTER) {
            next = spawn_ray(sp.p, sp.p_error, sp.ng, bs.wi, TRACE_OFFSET_SLACK);
            if (shadow_pending) {
                bool occluded = trace_occluded(shadow);
                if (!occluded) L += shadow_contrib;
                PATH_LOG(rec.shadow = occluded ? SHADOW_OCCLUDED : SHADOW_UNOCCLUDED;
                         rec.radiance = L);
            }
        }
        if (!scatter) {
            PATH_LOG(
                path_log_emit(rec, bs.lobe == LOBE_NONE ? TERM_NO_SCATTER : TERM_INCONSISTENT));
            break;
        }
        T *= bs.weight;
        prev_specular = (bs.lobe & LOBE_SPECULAR) != 0u;
        prev_pdf = bs.pdf;
        PATH_LOG(rec.rng[RNG_ROULETTE] = lobe_roulette.y;
                 rec.roulette_q = roulette_survival(T, bounce + 1u, params.min_depth));
        if (!roulette_apply(T, bounce + 1u, params.min_depth, lobe_roulette.y)) {
            PATH_LOG(rec.throughput = T; path_log_emit(rec, TERM_ROULETTE));
            break;
        }
        ray = TRACE_SHADOW_AFTER_SCATTER
                  ? next
                  : spawn_ray(sp.p, sp.p_error, sp.ng, bs.wi, TRACE_OFFSET_SLACK);
        ++rays.extension;
        PATH_LOG(rec.throughput = T; path_log_emit(rec, TERM_CONTINUE));
    }
    return L;
}

#endif // TP_SHARED_INTEGRATOR_H
