#include "core/description/scene_hash.h"

#include <cstring>
#include <type_traits>

namespace wt {

namespace {

// Eight bytes at a time, each word mixed with the multiply-xorshift of splitmix64 (Steele et
// al. 2014): fast enough for a million-triangle mesh, and any changed bit changes the hash.
class Hasher {
public:
    void bytes(const void* data, std::size_t size) {
        const unsigned char* p = static_cast<const unsigned char*>(data);
        word(size);
        for (; size >= 8; p += 8, size -= 8) {
            uint64_t w;
            std::memcpy(&w, p, 8);
            word(w);
        }
        uint64_t tail = 0;
        if (size > 0) std::memcpy(&tail, p, size);  // an empty vector's data() may be null
        word(tail);
    }
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    template <class T>
    void array(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(v.data(), v.size() * sizeof(T));
    }
    void word(uint64_t w) {
        uint64_t z = state_ ^ (w + 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        state_ = z ^ (z >> 31);
    }
    uint64_t result() const { return state_; }

private:
    uint64_t state_ = 0x77617665747261ceull;  // "wavetra..."
};

}  // namespace

uint64_t scene_content_hash(const SceneDescription& d) {
    Hasher h;
    h.value(d.camera.eye), h.value(d.camera.look_at), h.value(d.camera.up), h.value(d.camera.fov_degrees);
    // Only a camera that is not the pinhole: a pinhole scene keeps the hash it had.
    if (d.camera.projection != Projection::perspective || d.camera.aperture_radius > 0.0f)
        h.value(d.camera.projection), h.value(d.camera.width_world), h.value(d.camera.aperture_radius),
            h.value(d.camera.focus_distance);
    h.word(d.materials.size());
    for (const Material& m : d.materials) {
        h.bytes(m.name.data(), m.name.size());  // names show in --debug-sample output
        h.value(m.type), h.value(m.albedo), h.value(m.sigma), h.value(m.reflectance), h.value(m.ior), h.value(m.emission);
        // Only the types that read them: the other materials keep the hashes they had.
        if (m.type >= MaterialType::conductor) h.value(m.roughness), h.value(m.f0), h.value(m.eta), h.value(m.k);
        if (m.type == MaterialType::principled) h.value(m.base_color), h.value(m.metallic);
        if (m.has_textures())
            h.value(m.color_texture), h.value(m.metallic_roughness_texture), h.value(m.normal_texture), h.value(m.normal_scale);
        // Only where there is one: the other scenes' hashes (and their checkpoints) stay as they were.
        if (m.emission_texture >= 0) h.value(m.emission_texture);
        if (m.is_alpha_tested())
            h.value(m.alpha_mode), h.value(m.alpha_factor), h.value(m.alpha_cutoff), h.value(m.alpha_texture);
    }
    h.word(d.meshes.size());
    for (const TriangleMesh& mesh : d.meshes) {
        h.array(mesh.vertices), h.array(mesh.triangles), h.array(mesh.normals);
        h.value(mesh.material), h.value(mesh.parallelogram);
        if (!mesh.uvs.empty()) h.array(mesh.uvs);
        if (!mesh.tangents.empty()) h.array(mesh.tangents);
        if (!mesh.second_uvs.empty()) h.array(mesh.second_uvs);
    }
    h.array(d.spheres);
    // Only when there are some: a scene without instances keeps the hash it had.
    if (!d.instances.empty()) {
        h.word(d.prototypes.size());
        for (const MeshPrototype& p : d.prototypes) {
            h.bytes(p.name.data(), p.name.size());
            h.word(p.parts.size());
            for (const TriangleMesh& mesh : p.parts) {
                h.array(mesh.vertices), h.array(mesh.triangles), h.array(mesh.normals), h.value(mesh.material);
                if (!mesh.uvs.empty()) h.array(mesh.uvs);
                if (!mesh.tangents.empty()) h.array(mesh.tangents);
                if (!mesh.second_uvs.empty()) h.array(mesh.second_uvs);
            }
        }
        h.word(d.instances.size());
        for (const InstanceDescription& k : d.instances) h.value(k.prototype), h.value(k.transform);
    }
    // Only when there are some, as the lights below.
    if (!d.textures.empty()) {
        h.word(d.textures.size());
        for (const TextureImage& t : d.textures) {
            h.value(t.srgb), h.value(t.wrap_s), h.value(t.wrap_t), h.value(t.offset), h.value(t.scale), h.value(t.rotation);
            if (t.coordinate_set != 0) h.value(t.coordinate_set);
            h.word(uint64_t(t.texels->width)), h.word(uint64_t(t.texels->height)), h.array(t.texels->rgba);
        }
    }
    // Only when there are some: a scene without the list keeps the hash it had.
    if (!d.lights.empty()) {
        h.word(d.lights.size());
        for (const LightDescription& l : d.lights) {
            h.value(l.type), h.value(l.radiance), h.value(l.strength), h.value(l.rotate_degrees), h.value(l.position);
            h.value(l.intensity), h.value(l.direction), h.value(l.cone_degrees), h.value(l.blend), h.value(l.irradiance);
            h.value(l.angle_degrees);
            if (l.map) h.word(uint64_t(l.map->width)), h.word(uint64_t(l.map->height)), h.array(l.map->rgb);
        }
    }
    return h.result();
}

std::string hash_to_hex(uint64_t hash) {
    static const char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 15; i >= 0; --i, hash >>= 4) s[std::size_t(i)] = digits[hash & 15];
    return s;
}

}  // namespace wt
