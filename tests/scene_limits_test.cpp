// The scene loader against hostile input: nesting, sizes and files that made it crash, hang or
// take quadratic time. The sizes are chosen so the old quadratic paths would run for minutes,
// past ctest's timeout for these tests, while linear ones take a fraction of a second.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cfloat>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/import/imported_mesh.h"
#include "core/import/mesh_file.h"
#include "core/base/printable.h"
#include "core/system/regular_file.h"
#include "core/scene_file/json_parse.h"
#include "scene_test_helpers.h"

namespace {

namespace fs = std::filesystem;

std::string nested_arrays(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(HostileScene, DeepNestingInsideAFieldIsRefusedNamingTheField) {
    // 80,000 levels overflowed the stack when the message printed the value.
    expect_scene_error(replaced("\"eye\": [0, 0, 0]", "\"eye\": " + nested_arrays(80000)),
                       "camera.eye[0][0]");
    expect_scene_error(replaced("\"eye\": [0, 0, 0]", "\"eye\": " + nested_arrays(80000)),
                       "JSON nested deeper than 64 levels");
}

TEST(HostileScene, DeepNestingAtTheTopLevelIsRefused) {
    expect_scene_error(nested_arrays(200000), "JSON nested deeper than 64 levels");
}

TEST(HostileScene, NestingUpToTheLimitIsOnlyATypeError) {
    // 63 arrays inside "eye" (depth 64 with the root object and camera): parsed, then refused
    // as a vec3 like any other wrong value.
    expect_scene_error(replaced("\"eye\": [0, 0, 0]", "\"eye\": " + nested_arrays(wt::kMaxJsonDepth - 2)),
                       "camera.eye: expected an array of 3 numbers");
}

TEST(HostileScene, AnObjectWithFourHundredThousandKeysIsReadInLinearTime) {
    std::string keys;
    for (int i = 0; i < 400000; ++i) keys += "\"k" + std::to_string(i) + "\": 1, ";
    // Every key parsed and checked for repeats, then the first unknown one named.
    expect_scene_error(replaced("\"render\": {", "\"render\": {" + keys), "render.k0: unknown key");
    expect_scene_error(replaced("\"render\": {", "\"render\": {" + keys + "\"k399999\": 2, "),
                       "render.k399999: duplicate key \"k399999\"");
}

TEST(HostileScene, TwoHundredThousandMaterialsAndShapesLoadInLinearTime) {
    const int n = 200000;
    std::string materials, shapes;
    for (int i = 0; i < n; ++i) {
        materials += ",\"m" + std::to_string(i) + "\": {\"type\": \"lambertian\", \"albedo\": [0.5, 0.5, 0.5]}";
        shapes += ",{\"type\": \"sphere\", \"center\": [" + std::to_string(10 + i) +
                  ", 0, 0], \"radius\": 0.25, \"material\": \"m" + std::to_string(n - 1 - i) + "\"}";
    }
    std::string text = replaced("\"glass\": {\"type\": \"glass\", \"ior\": 1.5}",
                                "\"glass\": {\"type\": \"glass\", \"ior\": 1.5}" + materials);
    text.replace(text.find("\"material\": \"white\"}"), 20, "\"material\": \"white\"}" + shapes);
    const wt::SceneDescription scene = parse_scene_json(text, kSource);
    ASSERT_EQ(scene.materials.size(), std::size_t(5 + n));
    ASSERT_EQ(scene.spheres.size(), std::size_t(1 + n));
    // Sphere 1 + i names material m(n-1-i), stored at index 5 + n - 1 - i.
    EXPECT_EQ(scene.spheres[1].material, uint32_t(5 + n - 1));
    EXPECT_EQ(scene.spheres[n].material, 5u);
    EXPECT_EQ(scene.materials[scene.spheres[n].material].name, "m0");
}

TEST(HostileScene, AnUnknownMaterialAmongManyGivesAShortMessage) {
    std::string materials;
    for (int i = 0; i < 1000; ++i)
        materials += ",\"m" + std::to_string(i) + "\": {\"type\": \"lambertian\", \"albedo\": [0.5, 0.5, 0.5]}";
    const std::string text = replaced("\"glass\": {\"type\": \"glass\", \"ior\": 1.5}",
                                      "\"glass\": {\"type\": \"glass\", \"ior\": 1.5}" + materials);
    try {
        parse_scene_json(text.substr(0, text.find("\"material\": \"glass\"")) + "\"material\": \"nope\"" +
                             text.substr(text.find("\"material\": \"glass\"") + 19),
                         kSource);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("no material named \"nope\""), std::string::npos) << message;
        EXPECT_NE(message.find("1005 in all"), std::string::npos) << message;
        EXPECT_LT(message.size(), 600u) << message;
    }
}

TEST(HostileScene, FltMaxAsPrintedIsAFloatAndTheNextDigitIsNot) {
    // 3.4028235e38 is FLT_MAX to 8 digits: a little above FLT_MAX as a double, FLT_MAX as a float.
    const wt::SceneDescription scene = parse_scene_json(replaced("\"radius\": 1", "\"radius\": 3.4028235e38"), kSource);
    EXPECT_EQ(scene.spheres[0].radius, FLT_MAX);
    expect_scene_error(replaced("\"radius\": 1", "\"radius\": 3.4028236e38"), "shapes[0].radius: is too large for a 32-bit float");
}

TEST(HostileScene, SyntaxErrorsShowRawBytesEscaped) {
    for (const std::string& bad : {std::string("\xff\xfe"), std::string("\x1b[31m"), std::string("\"\xc3\x28\"")}) {
        try {
            parse_scene_json(replaced("\"spp\": 2", "\"spp\": " + bad), kSource);
            ADD_FAILURE() << "no error";
        } catch (const SceneError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("JSON syntax error"), std::string::npos) << message;
            for (const unsigned char c : message) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "raw byte " << int(c) << " in " << message;
        }
    }
    EXPECT_EQ(wt::printable("a\xff\n"), "a\\xff\\x0a");
}

// ---------------------------------------------------------------------------------------------
// Files that are not files

class HostileFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("wt_hostile_files_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    void expect_load_error(const std::string& path, const std::string& expected) {
        try {
            wt::load_scene_file(path);
            ADD_FAILURE() << path << ": no error; expected " << expected;
        } catch (const SceneError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(path + ":", 0), 0u) << message;
            EXPECT_NE(message.find(expected), std::string::npos) << message;
        }
    }

    fs::path dir_;
};

TEST_F(HostileFiles, DevZeroIsRefusedBeforeAnythingIsRead) {
    expect_load_error("/dev/zero", "a character device, not a regular file");
}

TEST_F(HostileFiles, AFifoIsRefusedWithoutWaitingForAWriter) {
    const std::string fifo = (dir_ / "scene.json").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expect_load_error(fifo, "a FIFO, not a regular file");
}

TEST_F(HostileFiles, ADirectoryIsRefused) { expect_load_error(dir_.string(), "a directory, not a regular file"); }

TEST_F(HostileFiles, AFileOverTheLimitIsRefusedUnread) {
    // Sparse: no disk space, and it is refused by its size before a byte is read.
    const std::string big = (dir_ / "big.json").string();
    { std::FILE* f = std::fopen(big.c_str(), "wb"); ASSERT_NE(f, nullptr); std::fclose(f); }
    fs::resize_file(big, wt::kMaxSceneFileBytes + 1);
    expect_load_error(big, "larger than the limit of 256 MiB");
    fs::resize_file(big, 0);
    expect_load_error(big, "JSON syntax error");  // a regular file within the limit is read
}

TEST_F(HostileFiles, AMeshFileThatIsAFifoOrADeviceIsRefused) {
    ASSERT_EQ(::mkfifo((dir_ / "fifo.ply").c_str(), 0600), 0);
    fs::create_symlink("/dev/zero", dir_ / "zero.obj");  // read through: the device, not the link
    const std::string scene = (dir_ / "scene.json").string();
    for (const auto& [file, kind] : {std::pair<std::string, std::string>{"fifo.ply", "a FIFO"}, {"zero.obj", "a character device"}}) {
        const std::string text = replaced("{\"type\": \"sphere\", \"center\": [5, 0, 0], \"radius\": 1, \"material\": \"glass\"}",
                                          "{\"type\": \"mesh_file\", \"file\": \"" + file + "\", \"material\": \"white\"}");
        std::FILE* f = std::fopen(scene.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs(text.c_str(), f);
        std::fclose(f);
        expect_load_error(scene, "shapes[0].file: " + (dir_ / file).string() + ": cannot open: " + kind + ", not a regular file");
    }
}

TEST_F(HostileFiles, FilesAMeshFileNamesAreOpenedOnlyIfRegular) {
    // An OBJ's mtllib naming /dev/zero: the materials are skipped with a note, not read forever.
    fs::create_symlink("/dev/zero", dir_ / "zero.mtl");
    const std::string obj = (dir_ / "m.obj").string();
    {
        std::FILE* f = std::fopen(obj.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs("mtllib zero.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", f);
        std::fclose(f);
    }
    const wt::ImportedMesh mesh = wt::read_mesh_file(obj);
    EXPECT_EQ(mesh.triangles.size(), 1u);
    ASSERT_EQ(mesh.notes.size(), 1u);
    EXPECT_NE(mesh.notes[0].find("a character device, not a regular file"), std::string::npos) << mesh.notes[0];
    // A glTF buffer whose uri is a FIFO: an error naming it, not a wait for a writer.
    ASSERT_EQ(::mkfifo((dir_ / "buffer.bin").c_str(), 0600), 0);
    const std::string gltf = (dir_ / "m.gltf").string();
    {
        std::FILE* f = std::fopen(gltf.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs(R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "buffer.bin", "byteLength": 36}]})", f);
        std::fclose(f);
    }
    try {
        wt::read_mesh_file(gltf);
        ADD_FAILURE() << "no error";
    } catch (const wt::MeshFileError& e) {
        EXPECT_NE(std::string(e.what()).find("a FIFO, not a regular file"), std::string::npos) << e.what();
    }
}

}  // namespace
