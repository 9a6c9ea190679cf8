#include "scenes.h"

#include "scene/load.h"
#include "support/test_paths.h"

namespace tp::test {

FlatScene small_scene(const std::string& name, uint32_t width, uint32_t height,
                      const SceneOverrides& camera) {
    std::vector<std::string> warnings;
    Scene scene = load_scene(scenes_dir() + "/" + name + ".json", warnings);
    SceneOverrides o = camera;
    o.width = width;
    o.height = height;
    apply_overrides(scene, o);
    return flatten(scene);
}

FlatScene brighter(FlatScene scene, float scale) {
    for (Material& m : scene.materials) m.ke *= scale;
    for (Light& l : scene.lights) l.value *= scale;
    return scene;
}

} // namespace tp::test
