#pragma once
// Hand-built glTF 2.0 files for the accessor and primitive tests: one node holding one mesh,
// whose bufferViews, accessors and primitives a test adds one by one over a single buffer,
// written as a .gltf with the buffer in a base64 data URI (or as a .glb).

#include <string>

#include <nlohmann/json.hpp>

#include "import_test_files.h"

namespace wt::test {

// RFC 4648 base64, as a data URI carries a buffer (glTF 2.0, 3.6.1.2).
inline std::string base64(const std::string& bytes) {
    static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t group = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) group |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) group |= uint8_t(bytes[i + 2]);
        out += kDigits[(group >> 18) & 63];
        out += kDigits[(group >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(group >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[group & 63] : '=';
    }
    return out;
}

class GltfFile {
public:
    using Json = nlohmann::json;

    // Appends `bytes` (padded to 4) as a new bufferView; byteStride only if `stride` > 0.
    int view(const std::string& bytes, int stride = 0) {
        while (bin_.size() % 4) bin_ += '\0';
        Json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}};
        if (stride > 0) v["byteStride"] = stride;
        bin_ += bytes;
        views_.push_back(v);
        return int(views_.size()) - 1;
    }
    int accessor(const Json& a) {
        accessors_.push_back(a);
        return int(accessors_.size()) - 1;
    }
    Json& accessor_json(int index) { return accessors_[std::size_t(index)]; }
    // A FLOAT VEC3 accessor over a new bufferView of these positions.
    int positions(const std::vector<std::array<float, 3>>& points) {
        Bytes b;
        for (const auto& p : points) b.put(p[0]).put(p[1]).put(p[2]);
        return accessor({{"bufferView", view(b.str())}, {"componentType", 5126}, {"count", points.size()}, {"type", "VEC3"}});
    }
    // An index accessor of `component_type` (5121, 5123 or 5125) over a new bufferView.
    int indices(const std::vector<uint32_t>& values, int component_type) {
        Bytes b;
        for (uint32_t v : values) {
            if (component_type == 5121) b.put(uint8_t(v));
            else if (component_type == 5123) b.put(uint16_t(v));
            else b.put(v);
        }
        return accessor({{"bufferView", view(b.str())}, {"componentType", component_type}, {"count", values.size()}, {"type", "SCALAR"}});
    }
    void primitive(const Json& p) { primitives_.push_back(p); }

    Json json(const std::string& buffer_uri) const {
        Json buffer = {{"byteLength", bin_.size()}};
        if (!buffer_uri.empty()) buffer["uri"] = buffer_uri;
        return {{"asset", {{"version", "2.0"}}}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", {{{"mesh", 0}}}},
                {"meshes", {{{"primitives", primitives_}}}}, {"buffers", {buffer}}, {"bufferViews", views_},
                {"accessors", accessors_}};
    }
    // The .gltf text, its buffer in a data URI.
    std::string gltf() const { return json("data:application/octet-stream;base64," + base64(bin_)).dump(); }
    std::string glb_bytes() const { return glb(json("").dump(), bin_); }
    const std::string& bin() const { return bin_; }

private:
    std::string bin_;
    Json views_ = Json::array(), accessors_ = Json::array(), primitives_ = Json::array();
};

}  // namespace wt::test
