#include "core/import/gltf_accessor.h"

#include "core/import/imported_mesh.h"

namespace wt {
namespace {

std::string type_name(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    }
    return std::to_string(type);
}

std::string count_text(long double n, const char* what) {
    return std::to_string((unsigned long long)n) + " " + what;
}

// One unsigned index of a sparse accessor (UNSIGNED_BYTE, _SHORT or _INT, as checked).
uint32_t read_index(const unsigned char* p, int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return v; }
    default: { uint32_t v; std::memcpy(&v, p, 4); return v; }
    }
}

}  // namespace

std::string gltf_component_type_name(int component_type) {
    const char* name = nullptr;
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: name = "BYTE"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: name = "UNSIGNED_BYTE"; break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: name = "SHORT"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: name = "UNSIGNED_SHORT"; break;
    case TINYGLTF_COMPONENT_TYPE_INT: name = "INT"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: name = "UNSIGNED_INT"; break;
    case TINYGLTF_COMPONENT_TYPE_FLOAT: name = "FLOAT"; break;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: name = "DOUBLE"; break;
    }
    return (name ? std::string(name) + " (" : "(") + std::to_string(component_type) + ")";
}

GltfAccessor::GltfAccessor(const tinygltf::Model& model, int index, int type, std::initializer_list<int> component_types,
                           std::string context)
    : model_(model), context_(std::move(context)) {
    if (index < 0 || std::size_t(index) >= model.accessors.size()) fail("does not exist");
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    if (a.type != type) fail("expected type " + type_name(type) + ", got " + type_name(a.type));
    bool allowed = false;
    std::string names;
    for (const int c : component_types) {
        allowed |= a.componentType == c;
        names += (names.empty() ? "" : c == *(component_types.end() - 1) ? " or " : ", ") + gltf_component_type_name(c);
    }
    if (!allowed) fail("componentType " + gltf_component_type_name(a.componentType) + ", expected " + names);
    count_ = a.count;
    component_type_ = a.componentType;
    element_size_ = std::size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)) *
                                tinygltf::GetNumComponentsInType(uint32_t(a.type)));
    if (a.bufferView >= 0) {
        if (std::size_t(a.bufferView) < model.bufferViews.size()) {
            const std::size_t stride = model.bufferViews[std::size_t(a.bufferView)].byteStride;
            if (stride != 0 && stride < element_size_)
                fail("bufferView " + std::to_string(a.bufferView) + " has byteStride " + std::to_string(stride) +
                     ", less than one element (" + std::to_string(element_size_) + " bytes)");
            stride_ = stride != 0 ? stride : element_size_;  // no byteStride: tightly packed
        }
        // In long double, so a huge count cannot wrap the byte count around to a small one.
        const long double needed = (long double)stride_ * (long double)(count_ ? count_ - 1 : 0) + (long double)element_size_;
        if (count_ > 0) data_ = view_bytes(a.bufferView, (long double)a.byteOffset, needed, true, count_text(count_, "elements"));
    } else if (count_ > kMaxElementsWithoutBufferView) {
        fail("count " + std::to_string(count_) + " without a bufferView: more than 2^24 elements of zeros");
    }
    if (a.sparse.isSparse) open_sparse(a);
}

void GltfAccessor::fail(const std::string& what) const { throw MeshFileError(context_ + ": " + what); }

const unsigned char* GltfAccessor::view_bytes(int view, long double offset, long double size, bool may_have_stride,
                                              const std::string& what) const {
    const std::string name = "bufferView " + std::to_string(view);
    if (view < 0 || std::size_t(view) >= model_.bufferViews.size()) fail(what + ": " + name + " does not exist");
    const tinygltf::BufferView& v = model_.bufferViews[std::size_t(view)];
    if (!may_have_stride && v.byteStride != 0)
        fail(what + ": " + name + " has a byteStride, which the data of a sparse accessor must not have (it is tightly packed)");
    if (v.buffer < 0 || std::size_t(v.buffer) >= model_.buffers.size())
        fail(name + ": buffer " + std::to_string(v.buffer) + " does not exist");
    const std::vector<unsigned char>& buffer = model_.buffers[std::size_t(v.buffer)].data;
    if ((long double)v.byteOffset + (long double)v.byteLength > (long double)buffer.size())
        fail(name + " ends at byte " + std::to_string((unsigned long long)((long double)v.byteOffset + v.byteLength)) +
             " of buffer " + std::to_string(v.buffer) + ", which has only " + std::to_string(buffer.size()) +
             " bytes (the buffer is too short)");
    if (offset < 0 || offset + size > (long double)v.byteLength)
        fail(what + " need " + std::to_string((unsigned long long)(offset + size)) + " bytes of " + name + ", which has " +
             std::to_string(v.byteLength));
    return buffer.data() + v.byteOffset + std::size_t(offset);
}

// glTF 2.0, 3.6.2.3: `count` indices, strictly increasing and below the accessor's count, and
// as many values of the accessor's type, both tightly packed.
void GltfAccessor::open_sparse(const tinygltf::Accessor& a) {
    const auto& s = a.sparse;
    if (s.count < 1 || std::size_t(s.count) > count_)
        fail("sparse.count " + std::to_string(s.count) + " is not between 1 and the accessor's count (" +
             std::to_string(count_) + ")");
    const int index_type = s.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail("sparse.indices.componentType " + gltf_component_type_name(index_type) +
             ", expected UNSIGNED_BYTE (5121), UNSIGNED_SHORT (5123) or UNSIGNED_INT (5125)");
    const std::size_t n = std::size_t(s.count);
    const std::size_t index_size = std::size_t(tinygltf::GetComponentSizeInBytes(uint32_t(index_type)));
    const unsigned char* indices = view_bytes(s.indices.bufferView, (long double)s.indices.byteOffset,
                                              (long double)n * index_size, false, "sparse.indices: " + count_text(n, "indices"));
    sparse_values_ = view_bytes(s.values.bufferView, (long double)s.values.byteOffset, (long double)n * element_size_, false,
                                "sparse.values: " + count_text(n, "values"));
    sparse_indices_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const uint32_t i = read_index(indices + k * index_size, index_type);
        if (i >= count_)
            fail("sparse.indices: index " + std::to_string(k) + " is " + std::to_string(i) + ", out of range (count " +
                 std::to_string(count_) + ")");
        if (k > 0 && i <= sparse_indices_[k - 1])
            fail("sparse.indices: index " + std::to_string(k) + " is " + std::to_string(i) + ", not above the one before (" +
                 std::to_string(sparse_indices_[k - 1]) + "): they must increase strictly");
        sparse_indices_[k] = i;
    }
}

}  // namespace wt
