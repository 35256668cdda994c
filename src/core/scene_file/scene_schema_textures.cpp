
#include "core/image_io/image_error.h"
#include "core/scene_file/scene_schema.h"
#include "core/textures/texture_file.h"

// A material's colour as a scene file gives it: [r, g, b], or an image texture
// {"texture": "wood.png", "factor": [r, g, b], "wrap": "repeat"}, the file relative to the scene's.

namespace wt {

namespace {

TextureWrap read_wrap(const Reader& in, const Json& j, const std::string& path) {
    const std::string wrap = in.text(j, path);
    if (wrap == "repeat") return TextureWrap::repeat;
    if (wrap == "clamp") return TextureWrap::clamp;
    if (wrap == "mirror") return TextureWrap::mirror;
    in.fail(path, "must be one of \"repeat\", \"clamp\", \"mirror\", got " + describe(j));
}

}  // namespace

glm::vec3 read_color_or_texture(const Reader& in, const Json& j, const std::string& path, std::vector<TextureImage>& textures,
                                int32_t& texture, bool at_most_one) {
    if (!j.is_object()) return in.color(j, path, at_most_one);
    in.check_keys(j, path, {"texture", "factor", "wrap"}, " for a texture");
    const std::string file_path = member_path(path, "texture");
    const std::string file = in.text(in.required(j, "texture", path), file_path);
    if (file.empty()) in.fail(file_path, "must not be empty");
    const std::string resolved = in.resolve(file);
    TextureImage image;
    image.name = resolved;
    image.srgb = colour_file_is_srgb(resolved);
    try {
        image.texels = read_texture_file(resolved);
    } catch (const ImageError& e) {
        in.fail(file_path, e.what());
    }
    if (const Json* wrap = in.optional(j, "wrap")) image.wrap_s = image.wrap_t = read_wrap(in, *wrap, member_path(path, "wrap"));
    textures.push_back(std::move(image));
    texture = int32_t(textures.size() - 1);
    const Json* factor = in.optional(j, "factor");
    return factor ? in.color(*factor, member_path(path, "factor"), at_most_one) : glm::vec3(1.0f);
}

}  // namespace wt
