#include "tools/render/reference_error_options.h"

namespace wt {

void add_reference_error_options(CLI::App& cmd, ReferenceErrorOptions& o) {
    cmd.add_option("--reference", o.reference_path,
                   "Reference image (linear EXR) of the render's size: print the error against it at each pass");
    cmd.add_option("--error-csv", o.csv_path,
                   "With --reference: write seconds,spp,rmse,rel_mse rows (one per pass) to this CSV file");
}

}  // namespace wt
