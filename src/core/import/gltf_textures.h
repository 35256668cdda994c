#pragma once
// A glTF file's textures as ours: each (image, sampler) pair a material names becomes one
// TextureImage of the mesh, its image decoded once however many textures use it (inside a .glb,
// as a data URI, or an external PNG/JPEG, whose bytes tinygltf hands over undecoded).

#include <memory>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/textures/texture_image.h"

namespace wt {

class GltfTextures {
public:
    // read: whether the file's materials are used (MeshFileUse::file_materials); without, add()
    // reads nothing and returns -1.
    GltfTextures(const std::string& path, const tinygltf::Model& model, std::vector<TextureImage>& out, bool read)
        : path_(path), model_(model), out_(out), decoded_(model.images.size()), read_(read) {}

    // Texture `index` of the file as a TextureImage appended to `out`, returning its index there,
    // with the KHR_texture_transform among the texture info's `extensions`. srgb: a colour
    // texture (baseColor, emissive). Throws MeshFileError naming the file, the
    // material and the field ("FILE: material \"panel\": baseColorTexture: image 0 (wood.png):
    // ...") for a texture or image that does not exist, cannot be read or is too large.
    const std::string& path() const { return path_; }
    // coordinate_set: the TEXCOORD_n it reads (TextureImage::coordinate_set).
    int add(int index, const tinygltf::ExtensionMap& extensions, bool srgb, const std::string& material,
            const std::string& field, int coordinate_set = 0);

private:
    std::shared_ptr<const TextureTexels> decode(int image, const std::string& context);

    const std::string& path_;
    const tinygltf::Model& model_;
    std::vector<TextureImage>& out_;
    std::vector<std::shared_ptr<const TextureTexels>> decoded_;
    bool read_;
};

// tinygltf's image loader: keeps the encoded bytes in image->image for GltfTextures to decode
// (only the images a material uses are, and through the image module like every other image).
// `loading_model` is the tinygltf::Model being loaded: an image in a bufferView is refused (false,
// the reason in `err`) unless the view lies within its buffer, which tinygltf 2.7 does not check
// before it hands over the view's bytes.
bool keep_encoded_image(tinygltf::Image* image, int index, std::string* err, std::string* warn, int, int,
                        const unsigned char* bytes, int size, void* loading_model);

}  // namespace wt
