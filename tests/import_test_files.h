#pragma once
// Small mesh files written by the import tests into a temporary directory, and the scenes that
// use them. The binary writers (PLY of either byte order, .glb) are ours, a few lines each.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/scene_file/scene_loader.h"

namespace wt::test {

// A fresh directory per test, removed with everything in it at the end.
class ImportTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("wavetrace-import-" + std::to_string(getpid()) + "-" + info->test_suite_name() + "-" + info->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    void write(const std::string& name, const std::string& bytes) const {
        std::filesystem::create_directories((dir_ / name).parent_path());
        // A new file, not the old one truncated: ext4 flushes a truncated-and-rewritten file to
        // disk on close (auto_da_alloc), which made the truncation tests wait on the disk.
        std::filesystem::remove(dir_ / name);
        std::ofstream out(dir_ / name, std::ios::binary);
        out << bytes;
        ASSERT_TRUE(out.good()) << "test bug: cannot write " << path(name);
    }

    // A scene in the test directory whose shapes are the given JSON text.
    std::string scene_text(const std::string& shapes, const std::string& materials = kMaterials) const {
        return R"({"camera": {"eye": [-5, 0, 0], "look_at": [0, 0, 0]}, "materials": )" + materials +
               R"(, "shapes": [)" + shapes + "]}";
    }

    SceneDescription load(const std::string& shapes, const std::string& materials = kMaterials) const {
        return parse_scene_json(scene_text(shapes, materials), path("scene.json"));
    }

    // One mesh_file shape with material "white" and the given extra keys.
    SceneDescription load_file(const std::string& file, const std::string& extra = "") const {
        return load(R"({"type": "mesh_file", "file": ")" + file + R"(", "material": "white")" + extra + "}");
    }

    // The SceneError for a scene with one mesh_file shape; fails the test if there is none.
    std::string error_for(const std::string& file, const std::string& extra = "") const {
        try {
            load_file(file, extra);
        } catch (const SceneError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no SceneError for " << file << extra;
        return "";
    }

    static constexpr const char* kMaterials =
        R"({"white": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]},
            "lamp": {"type": "lambertian", "albedo": [0, 0, 0], "emission": [4, 4, 4]}})";

    std::filesystem::path dir_;
};

// Every error from a mesh file names the scene file, the JSON path of the shape's file, the mesh
// file, and what is wrong.
inline void expect_mesh_error(const std::string& message, const std::string& mesh_file, const std::string& problem) {
    EXPECT_NE(message.find("scene.json: shapes[0].file: "), std::string::npos) << message;
    EXPECT_NE(message.find(mesh_file), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message << "\nexpected to contain: " << problem;
}

// Values appended in a chosen byte order.
class Bytes {
public:
    explicit Bytes(bool big_endian = false) : big_endian_(big_endian) {}
    template <typename T>
    Bytes& put(T value) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if (big_endian_) std::reverse(b, b + sizeof(T));
        data_.append(reinterpret_cast<const char*>(b), sizeof(T));
        return *this;
    }
    Bytes& text(const std::string& s) {
        data_ += s;
        return *this;
    }
    const std::string& str() const { return data_; }

private:
    bool big_endian_;
    std::string data_;
};

// A binary PLY with float x y z (and nx ny nz), faces as a uchar-counted int list.
inline std::string binary_ply(bool big_endian, const std::vector<std::array<float, 3>>& vertices,
                              const std::vector<std::vector<int32_t>>& faces,
                              const std::vector<std::array<float, 3>>& normals = {}) {
    Bytes b(big_endian);
    b.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") + " 1.0\n");
    b.text("comment written by the wavetrace tests\n");
    b.text("element vertex " + std::to_string(vertices.size()) + "\nproperty float x\nproperty float y\nproperty float z\n");
    if (!normals.empty()) b.text("property float nx\nproperty float ny\nproperty float nz\n");
    b.text("element face " + std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n");
    for (std::size_t v = 0; v < vertices.size(); ++v) {
        for (float c : vertices[v]) b.put(c);
        if (!normals.empty())
            for (float c : normals[v]) b.put(c);
    }
    for (const auto& f : faces) {
        b.put(uint8_t(f.size()));
        for (int32_t i : f) b.put(i);
    }
    return b.str();
}

// A .glb: 12-byte header, the JSON chunk (padded with spaces), the BIN chunk (padded with zeros).
inline std::string glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    Bytes b;
    b.put(uint32_t(0x46546C67)).put(uint32_t(2)).put(uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    b.put(uint32_t(json.size())).put(uint32_t(0x4E4F534A)).text(json);
    if (!bin.empty()) b.put(uint32_t(bin.size())).put(uint32_t(0x004E4942)).text(bin);
    return b.str();
}

}  // namespace wt::test
