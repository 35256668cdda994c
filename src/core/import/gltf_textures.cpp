#include "core/import/gltf_textures.h"

#include <climits>
#include <cmath>
#include <cstdint>

#include "core/image_io/image_error.h"
#include "core/import/imported_mesh.h"
#include "core/textures/texture_file.h"

namespace wt {

namespace {

TextureWrap wrap_of(int gl_wrap) {
    if (gl_wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::clamp;
    if (gl_wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::mirror;
    return TextureWrap::repeat;
}

// KHR_texture_transform's offset, rotation and scale; a value that is not a number (or not
// finite) is an error naming it.
void read_transform(const tinygltf::Value& t, const std::string& context, TextureImage& out) {
    const auto number = [&](const tinygltf::Value& v, const std::string& what) {
        if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
            throw MeshFileError(context + ": KHR_texture_transform." + what + " is not a finite number");
        return float(v.GetNumberAsDouble());
    };
    const auto pair = [&](const char* key, glm::vec2& value) {
        if (!t.Has(key)) return;
        const tinygltf::Value& v = t.Get(key);
        if (!v.IsArray() || v.ArrayLen() != 2) throw MeshFileError(context + ": KHR_texture_transform." + key + " is not 2 numbers");
        value = glm::vec2(number(v.Get(0), key), number(v.Get(1), key));
    };
    pair("offset", out.offset);
    pair("scale", out.scale);
    if (t.Has("rotation")) out.rotation = number(t.Get("rotation"), "rotation");
}

}  // namespace

bool keep_encoded_image(tinygltf::Image* image, int index, std::string* err, std::string*, int, int, const unsigned char* bytes,
                        int size, void* loading_model) {
    // tinygltf has checked that the view and its buffer exist, not that the view's bytes are in
    // the buffer: it passes &buffer.data[byteOffset] and byteLength as given (found by fuzz_gltf,
    // a read past the buffer's heap block), and byteLength cast to int.
    const auto* model = static_cast<const tinygltf::Model*>(loading_model);
    if (image->bufferView >= 0 && model) {
        const tinygltf::BufferView& view = model->bufferViews[std::size_t(image->bufferView)];
        const std::size_t buffer_bytes = model->buffers[std::size_t(view.buffer)].data.size();
        if (view.byteOffset > buffer_bytes || view.byteLength > buffer_bytes - view.byteOffset || view.byteLength > INT_MAX) {
            if (err)
                *err += "image " + std::to_string(index) + ": bufferView " + std::to_string(image->bufferView) + " (bytes " +
                        std::to_string(view.byteOffset) + " to " + std::to_string(uint64_t(view.byteOffset) + view.byteLength) +
                        ") runs past the end of buffer " + std::to_string(view.buffer) + " (" + std::to_string(buffer_bytes) +
                        " bytes)\n";
            return false;
        }
    }
    image->image.assign(bytes, bytes + (size > 0 ? size : 0));
    image->as_is = true;
    return true;
}

std::shared_ptr<const TextureTexels> GltfTextures::decode(int index, const std::string& context) {
    if (index < 0 || std::size_t(index) >= model_.images.size())
        throw MeshFileError(context + ": image " + std::to_string(index) + " does not exist");
    std::shared_ptr<const TextureTexels>& texels = decoded_[std::size_t(index)];
    if (texels) return texels;
    const tinygltf::Image& image = model_.images[std::size_t(index)];
    const bool external = image.bufferView < 0 && !image.uri.empty() && image.uri.rfind("data:", 0) != 0;
    const std::string name = "image " + std::to_string(index) + (external ? " (" + image.uri + ")" : "");
    // tinygltf leaves an external image it could not read empty, with a warning only.
    if (image.image.empty())
        throw MeshFileError(context + ": " + name + (external ? ": the file is missing or unreadable" : ": no image data"));
    try {
        texels = read_texture_bytes(name, image.image.data(), image.image.size());
    } catch (const ImageError& e) {
        throw MeshFileError(context + ": " + e.what());
    }
    return texels;
}

int GltfTextures::add(int index, const tinygltf::ExtensionMap& extensions, bool srgb, const std::string& material,
                      const std::string& field, int coordinate_set) {
    if (!read_) return -1;
    const std::string context = path_ + ": material \"" + material + "\": " + field;
    if (index < 0 || std::size_t(index) >= model_.textures.size())
        throw MeshFileError(context + ": texture " + std::to_string(index) + " does not exist");
    const tinygltf::Texture& texture = model_.textures[std::size_t(index)];
    TextureImage out;
    out.texels = decode(texture.source, context);
    out.name = path_ + ": " + field + " of \"" + material + "\"";
    out.srgb = srgb;
    out.coordinate_set = coordinate_set;
    if (texture.sampler >= 0) {
        if (std::size_t(texture.sampler) >= model_.samplers.size())
            throw MeshFileError(context + ": sampler " + std::to_string(texture.sampler) + " does not exist");
        const tinygltf::Sampler& s = model_.samplers[std::size_t(texture.sampler)];
        out.wrap_s = wrap_of(s.wrapS);
        out.wrap_t = wrap_of(s.wrapT);
    }
    if (const auto t = extensions.find("KHR_texture_transform"); t != extensions.end()) read_transform(t->second, context, out);
    out_.push_back(std::move(out));
    return int(out_.size() - 1);
}

}  // namespace wt
