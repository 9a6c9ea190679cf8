#include "scene/obj_files.h"

#include "scene/texture_slots.h"

#include <tbb/parallel_for.h>

namespace tp {

std::map<std::string, ObjFile> read_obj_files(const std::vector<std::string>& paths,
                                              uint32_t default_material) {
    std::map<std::string, ObjFile> files;
    for (const std::string& p : paths) files[p];
    std::vector<std::pair<const std::string, ObjFile>*> list;
    for (auto& f : files) list.push_back(&f);
    tbb::parallel_for(size_t(0), list.size(), [&](size_t i) {
        ObjFile& f = list[i]->second;
        try {
            f.parts = load_obj(list[i]->first, f.scene, default_material, f.warnings);
        } catch (...) {
            f.error = std::current_exception();
        }
    });
    return files;
}

std::vector<ObjPart> append_obj(const ObjFile& file, Scene& scene, uint32_t default_material,
                                std::vector<std::string>& warnings) {
    if (file.error) std::rethrow_exception(file.error);
    const Scene& from = file.scene;
    const uint32_t first_mesh = uint32_t(scene.meshes.size());
    const uint32_t first_material = uint32_t(scene.materials.size());
    for (size_t i = 0; i < from.materials.size(); ++i) {
        Material m = from.materials[i];
        // An MTL material reads one image, map_Kd; its image is shared by file name, as
        // load_obj shares it, and its slot by value.
        if (m.kd_texture != NO_TEXTURE) {
            TextureSlot slot = from.texture_slots[size_t(m.kd_texture)];
            const Texture& image = from.textures[slot.image];
            uint32_t index = 0;
            while (index < scene.textures.size() && scene.textures[index].name != image.name)
                ++index;
            if (index == scene.textures.size()) scene.textures.push_back(image);
            slot.image = index;
            m.kd_texture = add_texture_slot(scene, slot);
        }
        scene.materials.push_back(m);
        scene.material_names.push_back(from.material_names[i]);
    }
    scene.meshes.insert(scene.meshes.end(), from.meshes.begin(), from.meshes.end());
    scene.skipped_triangles += from.skipped_triangles;
    warnings.insert(warnings.end(), file.warnings.begin(), file.warnings.end());
    std::vector<ObjPart> parts = file.parts;
    for (ObjPart& p : parts) {
        p.mesh += first_mesh;
        if (p.material != default_material) p.material += first_material;
    }
    return parts;
}

} // namespace tp
