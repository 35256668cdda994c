#include "core/description/estimator_settings.h"

#include "core/base/enum_names.h"

namespace wt {

const char* name_of(SamplerKind s) {
    switch (s) {
        case SamplerKind::independent: return "independent";
        case SamplerKind::sobol: return "sobol";
        case SamplerKind::stratified: break;
    }
    return "stratified";
}
const char* name_of(LightSampling l) { return l == LightSampling::mis ? "mis" : "nee"; }

const char* name_of(CausticPaths c) {
    switch (c) {
        case CausticPaths::light_tracing: return "light_tracing";
        case CausticPaths::photons: return "photons";
        case CausticPaths::path: break;
    }
    return "path";
}
std::optional<CausticPaths> parse_caustic_paths(const std::string& s) {
    return parse_one_of(s, {CausticPaths::path, CausticPaths::light_tracing, CausticPaths::photons});
}

std::optional<SamplerKind> parse_sampler(const std::string& s) {
    return parse_one_of(s, {SamplerKind::independent, SamplerKind::stratified, SamplerKind::sobol});
}
std::optional<LightSampling> parse_light_sampling(const std::string& s) {
    return parse_one_of(s, {LightSampling::nee, LightSampling::mis});
}

const char* name_of(LightSelection l) {
    switch (l) {
        case LightSelection::power: return "power";
        case LightSelection::bvh: return "bvh";
        case LightSelection::area: return "area";
        case LightSelection::automatic: break;
    }
    return "auto";
}
std::optional<LightSelection> parse_light_selection(const std::string& s) {
    return parse_one_of(s, {LightSelection::automatic, LightSelection::area, LightSelection::power, LightSelection::bvh});
}

}  // namespace wt
