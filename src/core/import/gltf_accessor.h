#pragma once
// One glTF 2.0 accessor's elements as the specification defines them (section 3.6.2): the
// bufferView's bytes, or zeros when there is no bufferView, with a sparse accessor's values
// substituted at its indices (3.6.2.3). Every byte range is checked against its bufferView and
// buffer when the accessor is opened, so reading the elements cannot run past a buffer.

#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace wt {

class GltfAccessor {
public:
    // Accessor `index` of `model`, which must be of `type` (TINYGLTF_TYPE_*) with one of
    // `component_types`. Throws MeshFileError "CONTEXT: problem" (CONTEXT names the file and
    // the accessor's use) for a missing or ill-typed accessor, a byte range past its bufferView
    // or buffer, or sparse indices that are not strictly increasing below count.
    GltfAccessor(const tinygltf::Model& model, int index, int type, std::initializer_list<int> component_types,
                 std::string context);

    std::size_t count() const { return count_; }
    int component_type() const { return component_type_; }
    const std::string& context() const { return context_; }

    // Calls f(i, bytes) for every element in order; bytes holds element i's components.
    template <typename F>
    void for_each(F&& f) const {
        std::size_t next_sparse = 0;
        for (std::size_t i = 0; i < count_; ++i) {
            const unsigned char* bytes = kZeros;
            if (next_sparse < sparse_indices_.size() && sparse_indices_[next_sparse] == i)
                bytes = sparse_values_ + element_size_ * next_sparse++;
            else if (data_)
                bytes = data_ + stride_ * i;
            f(i, bytes);
        }
    }

    // An accessor without a bufferView has no bytes behind its count, so the count is capped:
    // a small file must not be able to ask for gigabytes of zeros.
    static constexpr std::size_t kMaxElementsWithoutBufferView = std::size_t(1) << 24;

private:
    [[noreturn]] void fail(const std::string& what) const;
    // The bytes [offset, offset + size) of bufferView `view`, checked; `what` names them.
    const unsigned char* view_bytes(int view, long double offset, long double size, bool may_have_stride,
                                    const std::string& what) const;
    void open_sparse(const tinygltf::Accessor& a);

    static constexpr unsigned char kZeros[64] = {};  // the largest element, a float MAT4

    const tinygltf::Model& model_;
    std::string context_;
    std::size_t count_ = 0;
    int component_type_ = 0;
    std::size_t element_size_ = 0;
    const unsigned char* data_ = nullptr;  // element i at data_ + i * stride_; null: zeros
    std::size_t stride_ = 0;
    std::vector<uint32_t> sparse_indices_;  // strictly increasing
    const unsigned char* sparse_values_ = nullptr;  // tightly packed, one per sparse index
};

// The name of a TINYGLTF_COMPONENT_TYPE_* for messages ("UNSIGNED_SHORT"), or its number.
std::string gltf_component_type_name(int component_type);

}  // namespace wt
