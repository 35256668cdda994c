// glTF 2.0 (.gltf with its .bin files, or .glb), parsed by tinygltf (see README.md,
// Dependencies). Every mesh primitive of mode TRIANGLES reachable from the scene's nodes becomes
// one piece placed by its node's world transform; the accessors are bounds-checked here, since
// a buffer too short for them would otherwise be read past its end.

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "core/import/gltf_materials.h"
#include "core/regular_file.h"
#include "core/import/mesh_file.h"

namespace wt {
namespace {

// The file mapped read-only, so its bytes are in memory once: the page cache's copy, which
// tinygltf parses (and copies a .glb's binary chunk out of), rather than a heap copy as well.
class MappedFile {
public:
    explicit MappedFile(const std::string& path) {
        const int fd = ::open(path.c_str(), O_RDONLY);
        if (fd < 0) throw MeshFileError(path + ": cannot open: " + std::strerror(errno));
        struct stat st {};
        if (::fstat(fd, &st) == 0) size_ = std::size_t(st.st_size);
        if (size_ > 0) data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
        const int mmap_errno = errno;
        ::close(fd);
        if (data_ == MAP_FAILED) throw MeshFileError(path + ": cannot map: " + std::strerror(mmap_errno));
    }
    ~MappedFile() {
        if (data_ && data_ != MAP_FAILED) ::munmap(data_, size_);
    }
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    const unsigned char* data() const { return static_cast<const unsigned char*>(data_); }
    std::size_t size() const { return size_; }

private:
    void* data_ = nullptr;
    std::size_t size_ = 0;
};

// Textures are not rendered; leaving the image bytes undecoded also spares their memory.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

glm::dmat4 local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)  // glTF stores x, y, z, w
        m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// The bytes of one accessor's elements: element i starts at data + i * stride.
struct AccessorBytes {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int component_type = 0;
};

class GltfReader {
public:
    GltfReader(const std::string& path, const tinygltf::Model& model) : path_(path), model_(model) {}

    ImportedMesh read() {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (std::size_t(scene) >= model_.scenes.size()) fail("scene " + std::to_string(scene) + " does not exist");
            roots = model_.scenes[std::size_t(scene)].nodes;
        } else {
            // No scene: every node that is nobody's child is a root.
            std::vector<bool> is_child(model_.nodes.size(), false);
            for (const tinygltf::Node& n : model_.nodes)
                for (int c : n.children)
                    if (c >= 0 && std::size_t(c) < is_child.size()) is_child[std::size_t(c)] = true;
            for (std::size_t i = 0; i < model_.nodes.size(); ++i)
                if (!is_child[i]) roots.push_back(int(i));
        }
        for (int root : roots) visit(root, glm::dmat4(1.0), 0);
        if (!all_have_normals_) mesh_.normals.clear();
        if (!all_have_normals_ && any_have_normals_)
            mesh_.notes.push_back("some primitives have no NORMAL: the file's normals are not used");
        if (!any_material_) mesh_.triangle_materials.clear();
        for (const tinygltf::Material& m : model_.materials) mesh_.materials.push_back(map_gltf_material(m));
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw MeshFileError(path_ + ": " + what); }

    void visit(int index, const glm::dmat4& parent, int depth) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size()) fail("node " + std::to_string(index) + " does not exist");
        if (depth > 256) fail("node " + std::to_string(index) + ": the node hierarchy is deeper than 256 (a cycle?)");
        // Nodes may share children, so a small file can name exponentially many instances.
        if (++visits_ > (uint64_t(1) << 20)) fail("the node hierarchy places more than 2^20 node instances");
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 world = parent * local_transform(node);
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= model_.meshes.size())
                fail("node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) + " does not exist");
            const tinygltf::Mesh& mesh = model_.meshes[std::size_t(node.mesh)];
            for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
                read_primitive(mesh.primitives[p], "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p), world);
        }
        for (int child : node.children) visit(child, world, depth + 1);
    }

    AccessorBytes accessor(int index, const std::string& role, int type, const std::string& where) const {
        const std::string name = "accessor " + std::to_string(index) + " (" + role + " of " + where + ")";
        if (index < 0 || std::size_t(index) >= model_.accessors.size()) fail(name + " does not exist");
        const tinygltf::Accessor& a = model_.accessors[std::size_t(index)];
        if (a.sparse.isSparse) fail(name + ": sparse accessors are not supported");
        if (a.type != type) fail(name + ": expected type " + (type == TINYGLTF_TYPE_VEC3 ? "VEC3" : "SCALAR"));
        if (a.bufferView < 0 || std::size_t(a.bufferView) >= model_.bufferViews.size())
            fail(name + ": bufferView " + std::to_string(a.bufferView) + " does not exist");
        const tinygltf::BufferView& view = model_.bufferViews[std::size_t(a.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size())
            fail(name + ": buffer " + std::to_string(view.buffer) + " does not exist");
        const std::vector<unsigned char>& buffer = model_.buffers[std::size_t(view.buffer)].data;
        const int stride = a.ByteStride(view);
        if (stride <= 0) fail(name + ": invalid byteStride or component type");
        const std::size_t element = std::size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)) *
                                                tinygltf::GetNumComponentsInType(uint32_t(a.type)));
        // In long double, so a huge count cannot wrap the byte count around to a small one.
        const long double needed = (long double)a.byteOffset + (long double)stride * (long double)(a.count ? a.count - 1 : 0) +
                                   (long double)element;
        if (a.count > 0 && needed > (long double)view.byteLength)
            fail(name + ": " + std::to_string(a.count) + " elements need " + std::to_string((unsigned long long)needed) +
                 " bytes of bufferView " + std::to_string(a.bufferView) + ", which has " + std::to_string(view.byteLength));
        if (view.byteOffset + view.byteLength > buffer.size())
            fail(name + ": bufferView " + std::to_string(a.bufferView) + " ends at byte " +
                 std::to_string(view.byteOffset + view.byteLength) + " of buffer " + std::to_string(view.buffer) +
                 ", which has only " + std::to_string(buffer.size()) + " bytes (the buffer is too short)");
        return {buffer.data() + view.byteOffset + a.byteOffset, std::size_t(stride), a.count, a.componentType};
    }

    // FLOAT VEC3 elements; positions and normals must be finite.
    void read_vec3s(const AccessorBytes& bytes, const std::string& what, std::vector<glm::vec3>& out) const {
        if (bytes.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT) fail(what + ": expected FLOAT components");
        for (std::size_t i = 0; i < bytes.count; ++i) {
            glm::vec3 v;
            std::memcpy(&v, bytes.data + i * bytes.stride, sizeof v);
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                fail(what + ": element " + std::to_string(i) + " is not finite");
            out.push_back(v);
        }
    }

    void read_primitive(const tinygltf::Primitive& primitive, const std::string& where, const glm::dmat4& world) {
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
            mesh_.notes.push_back("skipped " + where + ": mode " + std::to_string(primitive.mode) +
                                  " is not TRIANGLES (4)");
            return;
        }
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(where + ": no POSITION attribute");
        const std::size_t first = mesh_.positions.size();
        const AccessorBytes positions = accessor(position->second, "POSITION", TINYGLTF_TYPE_VEC3, where);
        if (first + positions.count > UINT32_MAX)
            fail(where + ": the instances come to more than 2^32 - 1 vertices (the renderer's indices are 32-bit)");
        read_vec3s(positions, "accessor " + std::to_string(position->second) + " (POSITION of " + where + ")",
                   mesh_.positions);
        const auto normal = primitive.attributes.find("NORMAL");
        if (normal == primitive.attributes.end()) {
            all_have_normals_ = false;
        } else {
            any_have_normals_ = true;
            const AccessorBytes normals = accessor(normal->second, "NORMAL", TINYGLTF_TYPE_VEC3, where);
            if (normals.count != positions.count) fail(where + ": NORMAL and POSITION counts differ");
            read_vec3s(normals, "accessor " + std::to_string(normal->second) + " (NORMAL of " + where + ")", mesh_.normals);
        }
        if (!all_have_normals_) std::vector<glm::vec3>().swap(mesh_.normals);

        const std::size_t first_triangle = mesh_.triangles.size();
        if (primitive.indices < 0) {  // non-indexed: every three vertices are a triangle
            if (positions.count % 3 != 0) fail(where + ": " + std::to_string(positions.count) + " vertices, not a multiple of 3");
            for (std::size_t v = 0; v < positions.count; v += 3)
                mesh_.triangles.push_back({uint32_t(first + v), uint32_t(first + v + 1), uint32_t(first + v + 2)});
        } else {
            read_indices(primitive.indices, where, first, positions.count);
        }
        if (first_triangle == mesh_.triangles.size()) fail(where + ": no triangles");
        const bool has_material = primitive.material >= 0;
        if (has_material && std::size_t(primitive.material) >= model_.materials.size())
            fail(where + ": material " + std::to_string(primitive.material) + " does not exist");
        any_material_ |= has_material;
        mesh_.triangle_materials.resize(mesh_.triangles.size(),
                                        has_material ? uint32_t(primitive.material) : ImportedMesh::kNoMaterial);
        mesh_.pieces.push_back({first, positions.count, world});
    }

    void read_indices(int index, const std::string& where, std::size_t first, std::size_t vertex_count) {
        const AccessorBytes bytes = accessor(index, "indices", TINYGLTF_TYPE_SCALAR, where);
        const std::string name = "accessor " + std::to_string(index) + " (indices of " + where + ")";
        if (bytes.count % 3 != 0) fail(name + ": " + std::to_string(bytes.count) + " indices, not a multiple of 3");
        std::array<uint32_t, 3> triangle{};
        for (std::size_t i = 0; i < bytes.count; ++i) {
            const unsigned char* p = bytes.data + i * bytes.stride;
            uint32_t v = 0;
            switch (bytes.component_type) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = *p; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, p, 2); v = s; break; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&v, p, 4); break;
            default: fail(name + ": indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
            }
            if (v >= vertex_count)
                fail(name + ": index " + std::to_string(i) + " is " + std::to_string(v) + ", out of range (" +
                     std::to_string(vertex_count) + " vertices)");
            triangle[i % 3] = uint32_t(first + v);
            if (i % 3 == 2) mesh_.triangles.push_back(triangle);
        }
    }

    std::string path_;
    const tinygltf::Model& model_;
    ImportedMesh mesh_;
    bool all_have_normals_ = true;
    bool any_have_normals_ = false;
    uint64_t visits_ = 0;
    bool any_material_ = false;
};

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

ImportedMesh read_gltf_file(const std::string& path) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    loader.SetFsCallbacks({&referenced_file_exists, &tinygltf::ExpandFilePath, &read_referenced_file, &tinygltf::WriteWholeFile, nullptr});
    tinygltf::Model model;
    std::string err, warn;
    {
        // Unmapped before the accessors are read: the model holds its own copy of the buffers.
        const MappedFile file(path);
        if (file.size() > UINT32_MAX) throw MeshFileError(path + ": larger than 4 GiB, more than glTF's loader takes");
        const std::string base_dir = std::filesystem::path(path).parent_path().string();
        // The content decides, not the extension: a .glb starts with the magic "glTF".
        const bool binary = file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
        const bool ok =
            binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, file.data(), unsigned(file.size()), base_dir)
                   : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(file.data()),
                                                unsigned(file.size()), base_dir);
        if (!ok) throw MeshFileError(path + ": " + first_line(err.empty() ? warn : err));
    }
    ImportedMesh mesh = GltfReader(path, model).read();
    return mesh;
}

}  // namespace wt
