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

// A path between two of its vertices: what path_step needs to trace the next one. An engine
// that traces one sample per call runs path_radiance; one that gives a thread whose path has
// ended the next sample at once (shaders/render_items.glsl) keeps a PathState per thread and
// calls path_begin and path_step itself. Either way a sample draws the same numbers and traces
// the same rays.
struct PathState {
    RngKey key;
    Ray ray; // the next ray to trace
    vec3 L;  // radiance gathered so far: the sample's estimate once the path has ended
    vec3 T;  // throughput up to the origin of `ray`
    float prev_pdf;
    uint bounce; // scattering events so far
    uint sample_index;
    bool prev_specular; // the last scattering was specular, or `ray` is the camera ray
};

// Sample `sample_index` of pixel (x, y) before its first vertex: the camera ray.
PathState path_begin(uint x, uint y, uint sample_index, INOUT(RayCounts) rays) {
    PathState st;
    st.key = rng_key(params.sampler_id, params.seed, y * params.camera.width + x, sample_index);
    st.ray = camera_ray(params.camera, st.key, x, y);
    ++rays.camera;
    st.L = vec3(0.0f);
    st.T = vec3(1.0f);
    st.prev_pdf = 0.0f;
    st.bounce = 0u;
    st.sample_index = sample_index;
    st.prev_specular = true; // emitters seen directly get full weight
    return st;
}

// The path's next vertex, where st.ray met `hit` (`found` false: it escaped): emission there,
// next-event estimation, scattering and the roulette, and the ray after it. Returns false once
// the path has ended. For an engine that finds the hits of several paths' rays together.
bool path_at_hit(INOUT(PathState) st, bool found, TraceHit hit, INOUT(RayCounts) rays) {
    PathVertex rec;
    PATH_LOG(rec = path_vertex_begin(st.sample_index, st.bounce, st.ray));
    if (!found) {
        if (features_environment(scene_features) && params.env_light != NO_INDEX) {
            float light_pdf =
                scene_light_selection_pdf(params.env_light) * scene_environment_pdf(st.ray.dir);
            float mis = emission_mis_weight(st.prev_specular, st.prev_pdf, light_pdf);
            st.L += st.T * scene_environment_radiance(st.ray.dir) * mis;
            PATH_LOG(rec.emitted = st.T * scene_environment_radiance(st.ray.dir) * mis;
                     rec.mis_emission = mis);
        }
        PATH_LOG(rec.radiance = st.L; path_log_emit(rec, TERM_ESCAPED));
        return false;
    }
    uint light_offset = instances[hit.instance].light_offset;
    SurfacePoint sp = scene_surface(hit);
    surface_snap_to_ray(sp, st.ray.origin, st.ray.dir);
    Material mat = scene_material(hit.instance, sp);
    vec3 wo = -st.ray.dir;
    float cos_emit = dot(sp.ng, wo);
    // A PBR volume met from inside: the segment just traced crossed its medium (Beer-Lambert),
    // and the boundary's relative index is the reciprocal (pbr.h).
    if (feature_on(scene_features, FEATURE_PBR) && mat.type == MATERIAL_PBR && cos_emit < 0.0f &&
        pbr_is_volume(mat)) {
        st.T *= pbr_volume_transmittance(mat, hit.t);
        mat = pbr_material_at_side(mat, true);
    }
    PATH_LOG(rec.event = VERTEX_HIT; rec.t = hit.t; rec.instance = hit.instance;
             rec.primitive = hit.primitive; rec.bary = hit.bary;
             rec.material = instances[hit.instance].material; rec.position = sp.p;
             path_vertex_set_material(rec, mat));

    // 1. Emission, front face only.
    PATH_LOG(rec.cos_emit = cos_emit);
    if (feature_on(scene_features, FEATURE_EMISSIVE_TRIANGLES) && !is_black(mat.ke) &&
        cos_emit > 0.0f) {
        float light_pdf = 0.0f;
        if (light_offset != NO_INDEX) {
            uint li = light_offset + hit.primitive;
            light_pdf = scene_light_selection_pdf(li) *
                        triangle_light_pdf(lights[li].area, hit.t, cos_emit);
        }
        float mis = emission_mis_weight(st.prev_specular, st.prev_pdf, light_pdf);
        st.L += st.T * mat.ke * mis;
        PATH_LOG(rec.emitted = st.T * mat.ke * mis; rec.mis_emission = mis);
    }

    // 2. The maximum number of scattering events.
    PATH_LOG(rec.ng = sp.ng; rec.ns = sp.ns);
    if (st.bounce >= params.max_depth) {
        PATH_LOG(rec.radiance = st.L; path_log_emit(rec, TERM_MAX_DEPTH));
        return false;
    }
    if (!feature_on(scene_features, FEATURE_DIELECTRIC) || mat.type != MATERIAL_DIELECTRIC)
        surface_face_viewer(sp, wo);
    PATH_LOG(rec.ng = sp.ng; rec.ns = sp.ns);

    // 3. Next-event estimation. Where TRACE_SHADOW_AFTER_SCATTER holds, the shadow ray waits for
    // step 4 to be drawn; its contribution still reaches L before anything else does, so the
    // sums are the same in the same order.
    bool shadow_pending = false;
    Ray shadow = st.ray;
    vec3 shadow_contrib = vec3(0.0f);
    if (features_sample_lights(scene_features) && !material_is_delta_in(scene_features, mat) &&
        params.light_count > 0u) {
        uvec2 pick = rng_bounce2_bits(st.key, st.bounce, RNG_LIGHT_SLOT); // slot and alias coin
        uint slot = alias_slot_from_bits(pick.x, params.light_count);
        AliasEntry e = light_table[slot];
        uint li = alias_resolve(slot, e.prob, e.alias, uint_to_unit_float(pick.y));
        float sel_pdf = scene_light_selection_pdf(li);
        vec2 u = rng_bounce2(st.key, st.bounce, RNG_LIGHT_U);
        uvec2 env = rng_bounce2_bits(st.key, st.bounce, RNG_ENV_SLOT); // pixel slot and coin
        LightSample ls = scene_sample_light(li, sp.p, u, env.x, uint_to_unit_float(env.y));
        PATH_LOG(rec.light = li; rec.light_wi = ls.wi; rec.light_pdf = sel_pdf * ls.pdf;
                 rec.mis_light = 1.0f; rec.rng[RNG_LIGHT_SLOT] = uint_to_unit_float(pick.x);
                 rec.rng[RNG_LIGHT_COIN] = uint_to_unit_float(pick.y); rec.rng[RNG_LIGHT_U] = u.x;
                 rec.rng[RNG_LIGHT_V] = u.y; rec.rng[RNG_ENV_SLOT] = uint_to_unit_float(env.x);
                 rec.rng[RNG_ENV_COIN] = uint_to_unit_float(env.y));
        // A light on the viewer's side of the surface, or, for a material that transmits, on
        // either side where the shading normal agrees with the surface about which side it is.
        float side_g = dot(ls.wi, sp.ng);
        bool side_ok = material_transmits_in(scene_features, mat)
                           ? side_g != 0.0f && (side_g > 0.0f) == (dot(ls.wi, sp.ns) > 0.0f)
                           : side_g > 0.0f;
        if (ls.pdf > 0.0f && side_ok) {
            vec3 f = bsdf_eval_in(scene_features, mat, sp.ns, wo, ls.wi);
            PATH_LOG(rec.light_f = f);
            if (!is_black(f) && !is_black(ls.radiance)) {
                float light_pdf = sel_pdf * ls.pdf;
                // |cos|: a light behind a transmitting surface is below the shading normal.
                vec3 contrib = st.T * f * (abs(dot(sp.ns, ls.wi)) / light_pdf) * ls.radiance;
                if (features_mis(scene_features) && !ls.delta)
                    contrib *= power_heuristic(light_pdf,
                                               bsdf_pdf_in(scene_features, mat, sp.ns, wo, ls.wi));
                PATH_LOG(rec.light_bsdf_pdf = bsdf_pdf_in(scene_features, mat, sp.ns, wo, ls.wi);
                         rec.mis_light =
                             ls.delta ? 1.0f : power_heuristic(light_pdf, rec.light_bsdf_pdf);
                         rec.nee = contrib);
                ++rays.shadow;
                Ray sr = shadow_ray(sp.p, sp.p_error, sp.ng, ls, lights[li], TRACE_OFFSET_SLACK,
                                    SCENE_LIGHT_NORMAL_FROM_VERTICES);
                sr.tag = ray_tag(st.key, st.bounce, RAY_TAG_SHADOW);
                if (TRACE_SHADOW_AFTER_SCATTER) {
                    shadow_pending = true;
                    shadow = sr;
                    shadow_contrib = contrib;
                } else {
                    bool occluded = trace_occluded(sr);
                    if (!occluded) st.L += contrib;
                    PATH_LOG(rec.shadow = occluded ? SHADOW_OCCLUDED : SHADOW_UNOCCLUDED);
                }
            }
        }
    }

    // 4. Scattering. The lobe choice shares a Sobol pair with the roulette (rng.h); the pair
    // is drawn only where one of them is read (the roulette's number from min_depth on), and
    // a skipped draw leaves every other number as it is (rng.h's layout is fixed).
    bool lobe_or_roulette_read = bsdf_reads_lobe_choice_in(scene_features, mat) ||
                                 st.bounce + 1u >= params.min_depth || path_log_recording;
    vec2 lobe_roulette =
        lobe_or_roulette_read ? rng_bounce2(st.key, st.bounce, RNG_LOBE) : vec2(0.0f);
    vec2 dir_uv = rng_bounce2(st.key, st.bounce, RNG_DIR_U);
    BsdfSample bs = bsdf_sample_in(scene_features, mat, sp.ns, wo, lobe_roulette.x, dir_uv);
    PATH_LOG(rec.rng[RNG_LOBE] = lobe_roulette.x; rec.rng[RNG_DIR_U] = dir_uv.x;
             rec.rng[RNG_DIR_V] = dir_uv.y; rec.lobe = bs.lobe; rec.wi = bs.wi;
             rec.bsdf_pdf = bs.pdf; rec.bsdf_weight = bs.weight; rec.radiance = st.L;
             rec.throughput = st.T);
    bool scatter = bs.lobe != LOBE_NONE && scatter_is_consistent(sp.ng, wo, bs.wi, bs.lobe);
    Ray next = st.ray;
    if (TRACE_SHADOW_AFTER_SCATTER) {
        next = spawn_ray(sp.p, sp.p_error, sp.ng, bs.wi, TRACE_OFFSET_SLACK);
        next.tag = ray_tag(st.key, st.bounce + 1u, RAY_TAG_PATH);
        if (shadow_pending) {
            bool occluded = trace_occluded(shadow);
            if (!occluded) st.L += shadow_contrib;
            PATH_LOG(rec.shadow = occluded ? SHADOW_OCCLUDED : SHADOW_UNOCCLUDED;
                     rec.radiance = st.L);
        }
    }
    if (!scatter) {
        PATH_LOG(path_log_emit(rec, bs.lobe == LOBE_NONE ? TERM_NO_SCATTER : TERM_INCONSISTENT));
        return false;
    }
    st.T *= bs.weight;
    st.prev_specular = (bs.lobe & LOBE_SPECULAR) != 0u;
    st.prev_pdf = bs.pdf;
    PATH_LOG(rec.rng[RNG_ROULETTE] = lobe_roulette.y;
             rec.roulette_q = roulette_survival(st.T, st.bounce + 1u, params.min_depth));
    if (!roulette_apply(st.T, st.bounce + 1u, params.min_depth, lobe_roulette.y)) {
        PATH_LOG(rec.throughput = st.T; path_log_emit(rec, TERM_ROULETTE));
        return false;
    }
    if (!TRACE_SHADOW_AFTER_SCATTER) {
        next = spawn_ray(sp.p, sp.p_error, sp.ng, bs.wi, TRACE_OFFSET_SLACK);
        next.tag = ray_tag(st.key, st.bounce + 1u, RAY_TAG_PATH);
    }
    st.ray = next;
    ++rays.extension;
    PATH_LOG(rec.throughput = st.T; path_log_emit(rec, TERM_CONTINUE));
    ++st.bounce;
    return true;
}

// Traces the path's next vertex and makes the ray after it. Returns false once the path has
// ended.
bool path_step(INOUT(PathState) st, INOUT(RayCounts) rays) {
    TraceHit hit;
    bool found = trace_closest(st.ray, hit);
    return path_at_hit(st, found, hit, rays);
}

// Radiance estimate of sample `sample_index` of pixel (x, y); rays are counted into `rays`.
vec3 path_radiance(uint x, uint y, uint sample_index, INOUT(RayCounts) rays) {
    PathState st = path_begin(x, y, sample_index, rays);
    while (path_step(st, rays)) {
    }
    return st.L;
}

#endif // TP_SHARED_INTEGRATOR_H
