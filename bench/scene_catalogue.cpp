// The JSON of the generated benchmark scenes (docs/scene-format.md). Object transforms place
// each mesh from its bounding box in the asset file; the boxes below were measured from the
// files listed in ../shared/assets/README.md, which are fixed data.
#include "bench/scenes.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tp::bench {
namespace {

using nlohmann::json;

json v3(double x, double y, double z) {
    return json::array({x, y, z});
}

struct Box {
    std::array<double, 3> lo, hi;
};

// suzanne/suzanne.obj, bunny/stanford-bunny.obj, buddha/happy_buddha_112k.obj, teapot/teapot.obj
constexpr Box kSuzanne{{-3.86125, 0.267311, 3.25233}, {-1.126875, 2.236061, 4.955455}};
constexpr Box kBunny{{-0.09469, 0.032987, -0.061874}, {0.061009, 0.187321, 0.0588}};
constexpr Box kBuddha{{-20.33, 0.0, -20.3583}, {20.33, 99.0123, 20.3583}};
constexpr Box kTeapot{{-3.0, 0.0, -2.0}, {3.434, 3.15, 2.0}};

// An object that scales the mesh by `s`, turns it by `degrees` about +Y and stands it on the
// floor (y = 0) with its bounding-box centre above (x, z). M = T R S (docs/scene-format.md),
// so the translation is the target point minus R S of the box's bottom centre.
json placed(const std::string& mesh, const std::string& material, const Box& b, double s, double x,
            double z, double degrees = 0) {
    const double cx = 0.5 * (b.lo[0] + b.hi[0]), cz = 0.5 * (b.lo[2] + b.hi[2]);
    const double a = degrees * 3.14159265358979323846 / 180.0, c = std::cos(a), n = std::sin(a);
    // R_y(a) (cx, 0, cz) = (c cx + n cz, 0, -n cx + c cz)
    const double rx = s * (c * cx + n * cz), rz = s * (-n * cx + c * cz);
    json t = {{"scale", s}, {"translate", v3(x - rx, -s * b.lo[1], z - rz)}};
    if (degrees != 0) t["rotate"] = {{"axis", v3(0, 1, 0)}, {"degrees", degrees}};
    return {{"mesh", mesh}, {"material", material}, {"transform", t}};
}

json obj_mesh(const std::string& assets, const std::string& file) {
    return {{"type", "obj"}, {"file", assets + "/" + file}};
}

json phong(json kd, double ks = 0, double ns = 1) {
    return {{"type", "phong"}, {"Kd", std::move(kd)}, {"Ks", v3(ks, ks, ks)}, {"Ns", ns}};
}

json floor_object(double half_size) {
    return {{"mesh", "floor"},
            {"material", "floor"},
            {"transform", {{"scale", v3(half_size, 1, half_size)}}}};
}

json sky(double r, double g, double b) {
    return {{"type", "constant"}, {"radiance", v3(r, g, b)}};
}

json sun(json direction, double irradiance) {
    return {{"type", "directional"},
            {"direction", std::move(direction)},
            {"irradiance", v3(irradiance, irradiance, irradiance * 0.95)}};
}

json camera(json eye, json target, double fov) {
    return {{"eye", std::move(eye)}, {"target", std::move(target)}, {"fov", fov}};
}

// Thesis Table 5.3 "Monkeys": six Suzannes (6 x 968 triangles) and a floor quad, 5810
// triangles as in the table; two point lights and an environment. The monkeys cover little
// of the image, so most rays leave the scene. Phong exponents from 1 to 10^4.
json monkeys(const std::string& assets) {
    json s;
    s["camera"] = camera(v3(0, 2.0, 6.0), v3(0, 0.3, -0.75), 35);
    s["render"] = {{"max_depth", 8}, {"min_depth", 3}};
    s["materials"] = {{"floor", phong(v3(0.5, 0.5, 0.5))},
                      {"m0", phong(v3(0.7, 0.15, 0.1), 0.2, 10)},
                      {"m1", phong(v3(0.15, 0.5, 0.15), 0.4, 100)},
                      {"m2", phong(v3(0.1, 0.2, 0.6), 0.3, 1000)},
                      {"m3", phong(v3(0.6, 0.5, 0.1), 0.3, 50)},
                      {"m4", phong(v3(0.4, 0.4, 0.4), 0.5, 10000)},
                      {"m5", phong(v3(0.7, 0.7, 0.7))}};
    s["meshes"] = {{"suzanne", obj_mesh(assets, "suzanne/suzanne.obj")},
                   {"floor", {{"type", "quad"}}}};
    s["objects"] = json::array({floor_object(3.0)});
    for (int i = 0; i < 6; ++i)
        s["objects"].push_back(placed("suzanne", "m" + std::to_string(i), kSuzanne, 0.35,
                                      1.2 * (i % 3 - 1), -1.5 * (i / 3)));
    s["lights"] = json::array(
        {{{"type", "point"}, {"position", v3(-2, 3, 2)}, {"intensity", v3(6, 5.5, 5)}},
         {{"type", "point"}, {"position", v3(2.5, 2.5, 1)}, {"intensity", v3(3, 3.5, 4)}}});
    s["environment"] = sky(0.25, 0.3, 0.4);
    return s;
}

// Thesis "Bunny": the Stanford bunny large in the frame, on a floor, under a sun and a sky.
json bunny(const std::string& assets) {
    json s;
    s["camera"] = camera(v3(0.4, 0.9, 2.0), v3(0, 0.55, 0), 40);
    s["render"] = {{"max_depth", 8}, {"min_depth", 3}};
    s["materials"] = {{"floor", phong(v3(0.5, 0.5, 0.5))}, {"bunny", phong(v3(0.75, 0.72, 0.68))}};
    s["meshes"] = {{"bunny", obj_mesh(assets, "bunny/stanford-bunny.obj")},
                   {"floor", {{"type", "quad"}}}};
    s["objects"] = json::array({floor_object(4.0), placed("bunny", "bunny", kBunny, 8.0, 0, 0)});
    s["lights"] = json::array({sun(v3(-0.4, -1, -0.5), 2.5)});
    s["environment"] = sky(0.3, 0.35, 0.45);
    return s;
}

// Thesis "Happy Buddhas": four Buddhas in a row. `instanced` loads the mesh once and places
// it four times (one BLAS, four instances); otherwise each Buddha is its own mesh, loaded
// from the same file, so the triangles are stored four times. Same image either way.
json buddhas(const std::string& assets, bool instanced) {
    json s;
    s["camera"] = camera(v3(0, 0.9, 2.6), v3(0, 0.5, 0), 40);
    s["render"] = {{"max_depth", 8}, {"min_depth", 3}};
    s["materials"] = {{"floor", phong(v3(0.5, 0.5, 0.5))},
                      {"gold", phong(v3(0.45, 0.32, 0.1), 0.35, 40)}};
    s["meshes"] = {{"floor", {{"type", "quad"}}}};
    s["objects"] = json::array({floor_object(4.0)});
    const double degrees[4] = {20, -10, 10, -20};
    for (int i = 0; i < 4; ++i) {
        const std::string mesh = instanced ? "buddha" : "buddha" + std::to_string(i);
        if (i == 0 || !instanced)
            s["meshes"][mesh] = obj_mesh(assets, "buddha/happy_buddha_112k.obj");
        s["objects"].push_back(placed(mesh, "gold", kBuddha, 0.01, 0.5 * i - 0.75, 0, degrees[i]));
    }
    s["lights"] = json::array({sun(v3(-0.3, -1, -0.6), 2.5)});
    s["environment"] = sky(0.3, 0.35, 0.45);
    return s;
}

json buddhas_unique(const std::string& assets) {
    return buddhas(assets, false);
}

json buddhas_instanced(const std::string& assets) {
    return buddhas(assets, true);
}

// rtxON (second seed): "chrome teapot and ice bunny on the marble floor" under a sun. Ice is a
// dielectric of index 1.31 as in the tutorial; the marble is generated (generators.h), a
// glossy floor.
json rtxon(const std::string& assets) {
    json s;
    s["camera"] = camera(v3(0, 0.55, 1.7), v3(0, 0.2, 0), 40);
    s["render"] = {{"max_depth", 10}, {"min_depth", 3}};
    s["textures"] = {{"marble",
                      {{"generator", "marble"},
                       {"size", 512},
                       {"scale", 6},
                       {"seed", 7},
                       {"colors", json::array({v3(0.92, 0.91, 0.88), v3(0.35, 0.33, 0.36)})}}}};
    json floor = phong(v3(0.85, 0.85, 0.85), 0.1, 200);
    floor["map_Kd"] = "marble";
    s["materials"] = {{"floor", floor},
                      {"chrome", {{"type", "mirror"}, {"Ks", v3(0.9, 0.9, 0.92)}}},
                      {"ice", {{"type", "dielectric"}, {"Ni", 1.31}, {"Tf", v3(0.85, 0.95, 1.0)}}}};
    s["meshes"] = {{"teapot", obj_mesh(assets, "teapot/teapot.obj")},
                   {"bunny", obj_mesh(assets, "bunny/stanford-bunny.obj")},
                   {"floor", {{"type", "quad"}}}};
    s["objects"] =
        json::array({floor_object(2.0), placed("teapot", "chrome", kTeapot, 0.12, -0.45, 0, 30),
                     placed("bunny", "ice", kBunny, 3.0, 0.45, 0.05)});
    s["lights"] = json::array({sun(v3(-0.5, -1, -0.35), 3.0)});
    s["environment"] = sky(0.35, 0.4, 0.5);
    return s;
}

// A mesh of a sized scene's family: its file, its bounding box and what the family is made of.
struct FamilyMesh {
    const char* family;
    const char* file;
    Box box;
};

constexpr FamilyMesh kFamilies[] = {
    {"buddhas", "buddha/happy_buddha_112k.obj", kBuddha},
    {"suzannes", "suzanne/suzanne.obj", kSuzanne},
};

const FamilyMesh& family_mesh(const std::string& family) {
    for (const FamilyMesh& f : kFamilies)
        if (family == f.family) return f;
    return kFamilies[0]; // parse_sized_scene gives only the families above
}

// N copies of a mesh, each scaled to a height of 1 and turned its own way about +Y, on a k x k
// grid (k = ceil(sqrt(N))) with a gap of half the mesh's width; the camera looks down at the
// grid's centre from 0.8 + 0.9 sides in front of its front row and 0.4 + 0.6 sides up, which
// keeps the whole grid in the 40° field of view at every N.
json sized(const std::string& assets, const FamilyMesh& f, uint32_t copies) {
    const Box& b = f.box;
    const double s = 1.0 / (b.hi[1] - b.lo[1]);
    const double width = s * std::max(b.hi[0] - b.lo[0], b.hi[2] - b.lo[2]);
    const double spacing = 1.5 * width;
    const uint32_t k = uint32_t(std::ceil(std::sqrt(double(copies))));
    const double extent = spacing * (k - 1) + width; // the grid's side
    json j;
    j["camera"] = camera(v3(0, 0.4 + 0.6 * extent, 0.8 + 1.4 * extent), v3(0, 0.3, 0), 40);
    j["render"] = {{"max_depth", 8}, {"min_depth", 3}};
    j["materials"] = {{"floor", phong(v3(0.5, 0.5, 0.5))},
                      {"gold", phong(v3(0.45, 0.32, 0.1), 0.35, 40)}};
    j["meshes"] = {{"floor", {{"type", "quad"}}}};
    j["objects"] = json::array({floor_object(0.5 * extent + 2.0)});
    for (uint32_t i = 0; i < copies; ++i) {
        const std::string mesh = f.family + std::string("_") + std::to_string(i);
        j["meshes"][mesh] = obj_mesh(assets, f.file);
        const double x = spacing * (double(i % k) - 0.5 * (k - 1));
        const double z = spacing * (double(i / k) - 0.5 * (k - 1));
        j["objects"].push_back(placed(mesh, "gold", b, s, x, z, double(i * 37 % 90) - 45));
    }
    j["lights"] = json::array({sun(v3(-0.3, -1, -0.6), 2.5)});
    j["environment"] = sky(0.3, 0.35, 0.45);
    return j;
}

} // namespace

const std::vector<std::string>& sized_scene_families() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const FamilyMesh& f : kFamilies) n.push_back(f.family);
        return n;
    }();
    return names;
}

std::optional<CatalogueEntry> find_catalogue_entry(const std::string& name) {
    for (const CatalogueEntry& e : scene_catalogue())
        if (e.name == name) return e;
    const std::optional<SizedScene> sized_scene = parse_sized_scene(name);
    if (!sized_scene) return std::nullopt;
    const FamilyMesh& f = family_mesh(sized_scene->family);
    const uint32_t copies = sized_scene->copies;
    return CatalogueEntry{
        name,
        fmt::format("{} distinct copies of {} on a floor", copies, f.file),
        {f.file},
        [&f, copies](const std::string& assets) { return sized(assets, f, copies); }};
}

const std::vector<CatalogueEntry>& scene_catalogue() {
    static const std::vector<CatalogueEntry> entries = {
        {"cornell", "the bundled Cornell box (area light)", {}, nullptr},
        {"monkeys",
         "thesis Monkeys: six Suzannes, two point lights, environment",
         {"suzanne/suzanne.obj"},
         monkeys},
        {"bunny",
         "thesis Bunny: the Stanford bunny, sun and sky",
         {"bunny/stanford-bunny.obj"},
         bunny},
        {"buddhas",
         "thesis Happy Buddhas: four unique copies of the mesh",
         {"buddha/happy_buddha_112k.obj"},
         buddhas_unique},
        {"buddhas_instanced",
         "thesis Happy Buddhas instanced: one mesh, four instances",
         {"buddha/happy_buddha_112k.obj"},
         buddhas_instanced},
        {"rtxon",
         "rtxON: chrome teapot and ice bunny (IOR 1.31) on procedural marble, sun",
         {"teapot/teapot.obj", "bunny/stanford-bunny.obj"},
         rtxon},
    };
    return entries;
}

} // namespace tp::bench
