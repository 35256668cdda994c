#include "tools/compare/compare_command.h"

#include <iostream>
#include <memory>

#include "core/image_io/rgb_image_input.h"
#include "core/image_metrics/image_metrics.h"
#include "tools/cli/error_report.h"

namespace wt {

CLI::App* add_compare_command(CLI::App& app, CompareCommandOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "compare", "Error of an image against a reference: RMSE, relMSE, PSNR, mean ratio, worst pixel per channel");
    // Existence is checked by the reader, whose message names the file the same way for all three.
    cmd->add_option("image", o.image_path, "Image to judge (EXR for linear radiance; an sRGB PNG is decoded)")->required();
    cmd->add_option("reference", o.reference_path, "Reference image of the same size")->required();
    cmd->add_option("--mask", o.mask_path, "Image of the same size; only pixels whose first channel is non-zero count");
    return cmd;
}

int run_compare_command(const CompareCommandOptions& o) {
    try {
        const RgbImage image = read_rgb_image(o.image_path);
        const RgbImage reference = read_rgb_image(o.reference_path);
        if (image.width != reference.width || image.height != reference.height)
            throw ImageError(o.image_path + " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " but " + o.reference_path + " is " + std::to_string(reference.width) + "x" +
                             std::to_string(reference.height) + ": the images must be the same size");
        std::vector<uint8_t> kept;
        if (o.mask_path) {
            const RgbImage mask = read_rgb_image(*o.mask_path);
            if (mask.width != image.width || mask.height != image.height)
                throw ImageError(*o.mask_path + ": the mask is " + std::to_string(mask.width) + "x" +
                                 std::to_string(mask.height) + " but the images are " + std::to_string(image.width) +
                                 "x" + std::to_string(image.height));
            kept = pixels_kept_by(mask);
            bool any = false;
            for (uint8_t k : kept) any = any || k;
            if (!any) throw ImageError(*o.mask_path + ": the mask keeps no pixel (its first channel is 0 everywhere)");
        }
        const ImageErrorReport report = image_error(image, reference, o.mask_path ? &kept : nullptr);
        std::cout << o.image_path << " against " << o.reference_path << ", " << image.width << "x" << image.height << ", "
                  << report.pixels << " pixels compared" << (o.mask_path ? " (mask " + *o.mask_path + ")" : "") << "\n";
        print_error_table(std::cout, report);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "wavetrace: error: " << e.what() << "\n";
        return 1;
    }
}

Subcommand compare_subcommand(CLI::App& app) {
    auto options = std::make_shared<CompareCommandOptions>();
    return {add_compare_command(app, *options), [options] { return run_compare_command(*options); }};
}

}  // namespace wt
