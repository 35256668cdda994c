#include "core/import/gltf_load.h"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>

#include "core/import/gltf_textures.h"
#include "core/import/gltf_version.h"
#include "core/import/mapped_file.h"
#include "core/import/mesh_file.h"
#include "core/system/regular_file.h"

namespace wt {

namespace {

// tinygltf quotes a data URI it cannot decode whole, and one may be megabytes of base64.
std::string with_data_uris_shortened(std::string message) {
    const auto is_base64 = [](char c) { return std::isalnum((unsigned char)c) || c == '+' || c == '/' || c == '='; };
    for (std::size_t at = message.find("base64,"); at != std::string::npos; at = message.find("base64,", at + 1)) {
        const std::size_t start = at + 7;
        std::size_t end = start;
        while (end < message.size() && is_base64(message[end])) ++end;
        if (end - start > 32) message.replace(start + 16, end - start - 16, "... (" + std::to_string(end - start) + " characters)");
    }
    return message;
}

// tinygltf's own FileExists opens the file, which blocks on a FIFO: stat() does not.
bool referenced_file_exists(const std::string& path, void*) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}

// A .bin (or image) file the glTF names, read as tinygltf would, but only if it is a regular
// file within the mesh-file limit: a uri of /dev/zero or a FIFO would otherwise never return.
bool read_referenced_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    try {
        const RegularFile in = open_regular_file(path, kMaxMeshFileBytes);
        out->resize(std::size_t(in.size));
        if (in.size > 0 && std::fread(out->data(), 1, out->size(), in.file.get()) != out->size()) {
            if (err) *err += path + ": cannot read all of its " + std::to_string(in.size) + " bytes\n";
            return false;
        }
        return true;
    } catch (const InputFileError& e) {
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
}

}  // namespace

tinygltf::Model load_gltf_model(const std::string& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    // The loader checks an image's bufferView against the buffers already loaded into `model`.
    loader.SetImageLoader(keep_encoded_image, &model);
    loader.SetFsCallbacks({&referenced_file_exists, &tinygltf::ExpandFilePath, &read_referenced_file, &tinygltf::WriteWholeFile, nullptr});
    std::string err, warn;
    {
        // Unmapped before the accessors are read: the model holds its own copy of the buffers.
        const MappedFile file(path);
        if (file.size() > UINT32_MAX) throw MeshFileError(path + ": larger than 4 GiB, more than glTF's loader takes");
        const std::string base_dir = std::filesystem::path(path).parent_path().string();
        // The content decides, not the extension: a .glb starts with the magic "glTF".
        const bool binary = file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
        if (binary) check_glb_container(path, file.data(), file.size());
        const bool ok =
            binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, file.data(), unsigned(file.size()), base_dir)
                   : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(file.data()),
                                                unsigned(file.size()), base_dir);
        if (!ok) {
            explain_gltf_refusal(path, file.data(), file.size(), binary);
            throw MeshFileError(path + ": " + with_data_uris_shortened(first_line(err.empty() ? warn : err)));
        }
    }
    check_gltf_version_and_extensions(path, model);
    return model;
}

}  // namespace wt
