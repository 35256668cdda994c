#include "core/import/gltf_version.h"

#include <cstdint>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

#include "core/import/imported_mesh.h"

namespace wt {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw MeshFileError(path + ": " + what); }

void check_version(const std::string& path, const std::string& version) {
    const std::string major = version.substr(0, version.find('.'));
    if (major == "1") fail(path, "glTF 1.0 is not supported (version 2.0 is)");
    if (major != "2") fail(path, "glTF " + version + " is not supported (version 2.0 is)");
}

// Extensions that change where or how the vertices are stored; without them the accessors we
// would read are empty, compressed or quantised. Material and texture extensions are not
// here: what they add is noted as not mapped, and the geometry is right.
void check_required(const std::string& path, const std::string& extension) {
    for (const char* geometry : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization",
                                 "EXT_mesh_gpu_instancing"})
        if (extension == geometry)
            fail(path, "requires extension " + extension + " (extensionsRequired), which is not supported");
}

}  // namespace

void check_glb_container(const std::string& path, const unsigned char* data, std::size_t size) {
    if (size < 8) return;  // tinygltf says what is wrong with so short a file
    const auto word = [&](std::size_t at) {
        uint32_t w = 0;
        std::memcpy(&w, data + at, 4);
        return w;
    };
    if (word(4) == 1) fail(path, "glTF 1.0 is not supported (version 2.0 is)");
    // Header: magic, version, length; then chunks of (length, type, bytes), JSON first.
    if (size < 20) return;
    const uint64_t length = word(8), bin_chunk = 20 + uint64_t(word(12));
    if (length > size || bin_chunk + 8 > length) return;  // tinygltf refuses these, or there is no BIN chunk
    const uint64_t bin_end = bin_chunk + 8 + word(std::size_t(bin_chunk));
    if (bin_end > length)
        fail(path, "the BIN chunk at byte " + std::to_string(bin_chunk) + " claims " + std::to_string(word(std::size_t(bin_chunk))) +
                       " bytes, which would end at byte " + std::to_string(bin_end) + ", past the " + std::to_string(length) +
                       " bytes of the file");
}

void check_gltf_version_and_extensions(const std::string& path, const tinygltf::Model& model) {
    check_version(path, model.asset.version);
    for (const std::string& e : model.extensionsRequired) check_required(path, e);
}

void explain_gltf_refusal(const std::string& path, const unsigned char* data, std::size_t size, bool binary) {
    using Json = nlohmann::json;
    const char* text = reinterpret_cast<const char*>(data);
    std::size_t length = size;
    if (binary) {  // header (12 bytes), then the JSON chunk's length and type, then the JSON
        uint32_t chunk = 0;
        if (size < 20) return;
        std::memcpy(&chunk, data + 12, 4);
        if (chunk > size - 20) return;
        text += 20;
        length = chunk;
    }
    // Only the top two levels are kept: what is looked at is there, and a deep file stays cheap.
    const Json::parser_callback_t shallow = [](int depth, Json::parse_event_t, Json&) { return depth <= 2; };
    const Json root = Json::parse(text, text + length, shallow, /*allow_exceptions=*/false);
    if (!root.is_object()) return;
    if (const auto extensions = root.find("extensionsRequired"); extensions != root.end() && extensions->is_array())
        for (const Json& e : *extensions)
            if (e.is_string()) check_required(path, e.get<std::string>());
    const auto asset = root.find("asset");
    if (asset != root.end() && asset->is_object()) {
        const auto version = asset->find("version");
        if (version != asset->end() && version->is_string()) check_version(path, version->get<std::string>());
        if (version != asset->end() && version->is_number()) check_version(path, version->dump());
        if (version != asset->end()) return;
    }
    for (const char* dictionary : {"accessors", "bufferViews", "buffers", "meshes", "nodes", "materials", "scenes"})
        if (const auto it = root.find(dictionary); it != root.end() && it->is_object())
            fail(path, "glTF 1.0 is not supported (version 2.0 is)");
}

}  // namespace wt
