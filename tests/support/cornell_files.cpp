#include "support/cornell_files.h"

#include "support/gltf_builder.h"
#include "support/test_paths.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <stdexcept>

namespace tp::test {

CornellFiles write_cornell_files(const std::string& dir) {
    using json = nlohmann::json;
    const json scene = read_json(scenes_dir() + "/cornell.json");
    // The bundled objects' quads in metres, grouped by material in the order each material
    // first appears (the OBJ loader makes one mesh per material).
    std::vector<std::string> order;
    std::map<std::string, std::vector<glm::vec3>> quads; // per material: 4 corners per quad
    for (const json& o : scene["objects"]) {
        const std::string mat = o["material"];
        if (!quads.count(mat)) order.push_back(mat);
        const double scale = o["transform"]["scale"];
        const json& mesh = scene["meshes"][o["mesh"].get<std::string>()];
        if (mesh["type"] != "triangles" || !mesh.contains("quads"))
            throw std::runtime_error("cornell.json: expected meshes of quads");
        for (const json& q : mesh["quads"])
            for (int k = 0; k < 4; ++k) {
                const json& p = mesh["vertices"][q[k].get<size_t>()];
                quads[mat].push_back(glm::vec3(float(p[0].get<double>() * scale),
                                               float(p[1].get<double>() * scale),
                                               float(p[2].get<double>() * scale)));
            }
    }

    std::ofstream mtl(dir + "/cornell.mtl"), obj(dir + "/cornell.obj");
    obj << "mtllib cornell.mtl\n";
    GltfBuilder g;
    std::vector<uint32_t> nodes;
    for (const std::string& mat : order) {
        const json& m = scene["materials"][mat];
        const glm::vec3 kd(m["Kd"][0].get<float>(), m["Kd"][1].get<float>(),
                           m["Kd"][2].get<float>());
        json gm = {{"name", mat},
                   {"pbrMetallicRoughness",
                    {{"baseColorFactor", {kd.x, kd.y, kd.z, 1.0}},
                     {"metallicFactor", 0.0},
                     {"roughnessFactor", 1.0}}},
                   {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}};
        mtl << fmt::format("newmtl {}\nKd {:.9g} {:.9g} {:.9g}\nNs 0\n", mat, kd.x, kd.y, kd.z);
        if (m.contains("Ke")) {
            const glm::vec3 ke(m["Ke"][0].get<float>(), m["Ke"][1].get<float>(),
                               m["Ke"][2].get<float>());
            const float strength = std::max(ke.x, std::max(ke.y, ke.z));
            const glm::vec3 factor = ke / strength;
            gm["emissiveFactor"] = {factor.x, factor.y, factor.z};
            gm["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
            const glm::vec3 product = factor * strength; // Ke = emissiveFactor * strength
            mtl << fmt::format("Ke {:.9g} {:.9g} {:.9g}\n", product.x, product.y, product.z);
        }
        const uint32_t material = g.add("materials", gm);
        // A quad's corners i, j, k, l are both loaders' triangles (i, j, k), (i, k, l); the OBJ
        // loader numbers a group's vertices in order of first use: i, j, k, l of each quad.
        const std::vector<glm::vec3>& c = quads[mat];
        std::vector<uint32_t> indices;
        obj << "usemtl " << mat << "\n";
        for (uint32_t q = 0; q < c.size(); q += 4) {
            for (uint32_t k = 0; k < 4; ++k)
                obj << fmt::format("v {:.17g} {:.17g} {:.17g}\n", double(c[q + k].x),
                                   double(c[q + k].y), double(c[q + k].z));
            obj << "f -4 -3 -2 -1\n";
            for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(q + k);
        }
        const uint32_t mesh =
            g.mesh({{"POSITION", g.vec3s(c)}}, int(g.indices(indices)), int(material));
        nodes.push_back(g.add("nodes", {{"name", mat}, {"mesh", mesh}}));
    }
    g.doc["extensionsUsed"] = {"KHR_materials_specular", "KHR_materials_emissive_strength"};
    g.scene(nodes);

    CornellFiles f;
    f.obj = dir + "/cornell.obj";
    f.glb = g.write_glb(dir, "cornell");
    f.gltf = g.write_gltf(dir, "cornell");
    const json& cam = scene["camera"];
    auto xyz = [](const json& v) {
        return fmt::format("{},{},{}", v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    };
    f.camera_flags = fmt::format("--eye {} --target {} --up {} --fov {}", xyz(cam["eye"]),
                                 xyz(cam["target"]), xyz(cam["up"]), cam["fov"].get<double>());
    return f;
}

} // namespace tp::test
