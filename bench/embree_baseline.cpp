#include "embree_baseline.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

#include "core/base/ray.h"

namespace wt::bench {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Attached with these ids, so a hit's geomID says which of our index ranges its primID is in.
constexpr unsigned kTriangleGeometry = 0;
constexpr unsigned kSphereGeometry = 1;
constexpr unsigned kQuadGeometry = 2;

void throw_on_device_error(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree: ") + what + " failed, error " + std::to_string(int(error)));
}

RTCIntersectContext context_for(bool coherent) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (coherent) context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    return context;
}

// A planar geometry of `count` primitives with K unshared corners each (3: Embree triangles,
// 4: Embree quads), corners_of(k, corners) giving primitive k's, attached to `scene` as `id`.
template <int K, typename CornersOf>
void attach_planar(RTCDevice device, RTCScene scene, unsigned id, std::size_t count, CornersOf corners_of) {
    static_assert(K == 3 || K == 4);
    RTCGeometry g = rtcNewGeometry(device, K == 4 ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), K * count));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, K == 4 ? RTC_FORMAT_UINT4 : RTC_FORMAT_UINT3, K * sizeof(unsigned), count));
    for (std::size_t k = 0; k < count; ++k) {
        glm::vec3 corners[K];
        corners_of(k, corners);
        for (std::size_t c = 0; c < std::size_t(K); ++c) {
            const std::size_t at = K * k + c;
            vertices[3 * at] = corners[c].x, vertices[3 * at + 1] = corners[c].y, vertices[3 * at + 2] = corners[c].z;
            indices[at] = unsigned(at);
        }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene, g, id);
    rtcReleaseGeometry(g);
}

float max_distance(const RayView& rays, uint32_t i) { return rays.tmax ? rays.tmax[i] : kInfinity; }

// One packet type's entry points, so closest and any hit are written once for 8 and 16 lanes.
template <int N>
struct EmbreePacket;

template <>
struct EmbreePacket<8> {
    using RayHit = RTCRayHit8;
    using Ray = RTCRay8;
    static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RayHit* r) { rtcIntersect8(valid, s, c, r); }
    static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Ray* r) { rtcOccluded8(valid, s, c, r); }
};

template <>
struct EmbreePacket<16> {
    using RayHit = RTCRayHit16;
    using Ray = RTCRay16;
    static void intersect(const int* valid, RTCScene s, RTCIntersectContext* c, RayHit* r) { rtcIntersect16(valid, s, c, r); }
    static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Ray* r) { rtcOccluded16(valid, s, c, r); }
};

// Fills lanes [0, lanes) of a packet from rays first ... first + lanes - 1 and marks them valid;
// the rest of the packet is masked off.
template <int N, typename PacketRay>
void load_packet(const RayView& rays, uint32_t first, int lanes, PacketRay& packet, int* valid) {
    for (int lane = 0; lane < N; ++lane) {
        valid[lane] = lane < lanes ? -1 : 0;
        if (lane >= lanes) continue;
        const uint32_t i = first + uint32_t(lane);
        packet.org_x[lane] = rays.ox[i], packet.org_y[lane] = rays.oy[i], packet.org_z[lane] = rays.oz[i];
        packet.dir_x[lane] = rays.dx[i], packet.dir_y[lane] = rays.dy[i], packet.dir_z[lane] = rays.dz[i];
        packet.tnear[lane] = 0.0f;
        packet.tfar[lane] = max_distance(rays, i);
        packet.time[lane] = 0.0f;
        packet.mask[lane] = ~0u;
        packet.id[lane] = i;
        packet.flags[lane] = 0;
    }
}

RTCDevice new_device(int threads) {
    const std::string config = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    if (!device) throw std::runtime_error("Embree: rtcNewDevice(\"" + config + "\") failed");
    return device;
}

// Each planar entry of ours as Embree's own primitive for it: parallelograms as quads v0,
// v0 + e1, v0 + e1 + e2, v0 + e2 (exact for the hexroom's integer corners), triangles as v0,
// v0 + e1, v0 + e2, rebuilt from the SoA buffers our kernels read; spheres as sphere points.
// rtcNewScene, the geometries and rtcCommitScene: what the build benchmark times.
RTCScene new_committed_scene(RTCDevice device, const Scene& our_scene) {
    RTCScene scene = rtcNewScene(device);
    const TriangleSoA& t = our_scene.triangles;
    if (t.parallelogram_count > 0) {
        attach_planar<4>(device, scene, kQuadGeometry, t.parallelogram_count, [&](std::size_t i, glm::vec3* c) {
            c[0] = t.vertex0(i), c[1] = c[0] + t.edge1(i), c[2] = c[1] + t.edge2(i), c[3] = c[0] + t.edge2(i);
        });
    }
    attach_planar<3>(device, scene, kTriangleGeometry, t.size() - t.parallelogram_count, [&](std::size_t k, glm::vec3* c) {
        const std::size_t i = t.parallelogram_count + k;
        c[0] = t.vertex0(i), c[1] = c[0] + t.edge1(i), c[2] = c[0] + t.edge2(i);
    });

    const SphereSoA& s = our_scene.spheres;
    if (s.size() > 0) {
        RTCGeometry spheres = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* points = static_cast<float*>(
            rtcSetNewGeometryBuffer(spheres, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), s.size()));
        for (std::size_t i = 0; i < s.size(); ++i) {
            points[4 * i + 0] = s.cx[i], points[4 * i + 1] = s.cy[i], points[4 * i + 2] = s.cz[i], points[4 * i + 3] = s.radius[i];
        }
        rtcCommitGeometry(spheres);
        rtcAttachGeometryByID(scene, spheres, kSphereGeometry);
        rtcReleaseGeometry(spheres);
    }
    rtcCommitScene(scene);
    throw_on_device_error(device, "building the scene");
    return scene;
}

}  // namespace

struct EmbreeBaseline::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    uint32_t triangle_count = 0;       // all planar entries, parallelograms included
    uint32_t parallelogram_count = 0;  // the first entries; Embree's quads

    uint32_t our_prim(unsigned geom_id, unsigned prim_id) const {
        if (geom_id == RTC_INVALID_GEOMETRY_ID) return kNoHit;
        if (geom_id == kQuadGeometry) return prim_id;
        return geom_id == kTriangleGeometry ? parallelogram_count + prim_id : triangle_count + prim_id;
    }

    template <int N>
    void closest_packets(const RayView& rays, const HitView& hits, bool coherent) const {
        RTCIntersectContext context = context_for(coherent);
        typename EmbreePacket<N>::RayHit packet;
        alignas(64) int valid[N];
        for (uint32_t first = 0; first < rays.count; first += N) {
            const int lanes = int(std::min<uint32_t>(N, rays.count - first));
            load_packet<N>(rays, first, lanes, packet.ray, valid);
            for (int lane = 0; lane < N; ++lane) packet.hit.geomID[lane] = packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
            EmbreePacket<N>::intersect(valid, scene, &context, &packet);
            for (int lane = 0; lane < lanes; ++lane) {
                const uint32_t i = first + uint32_t(lane);
                hits.prim[i] = our_prim(packet.hit.geomID[lane], packet.hit.primID[lane]);
                const bool found = hits.prim[i] != kNoHit;
                hits.t[i] = found ? packet.ray.tfar[lane] : kInfinity;
                hits.u[i] = packet.hit.u[lane];
                hits.v[i] = packet.hit.v[lane];
            }
        }
    }

    template <int N>
    void any_packets(const RayView& rays, uint8_t* occluded, bool coherent) const {
        RTCIntersectContext context = context_for(coherent);
        typename EmbreePacket<N>::Ray packet;
        alignas(64) int valid[N];
        for (uint32_t first = 0; first < rays.count; first += N) {
            const int lanes = int(std::min<uint32_t>(N, rays.count - first));
            load_packet<N>(rays, first, lanes, packet, valid);
            EmbreePacket<N>::occluded(valid, scene, &context, &packet);
            // Embree marks an occluded ray by setting its tfar to -infinity.
            for (int lane = 0; lane < lanes; ++lane) occluded[first + uint32_t(lane)] = packet.tfar[lane] < 0.0f;
        }
    }
};

EmbreeBaseline::EmbreeBaseline(const Scene& scene) : impl_(std::make_unique<Impl>()) {
    // One build thread: the benchmarks trace on one thread, and building is not what they time.
    impl_->device = new_device(1);
    impl_->scene = new_committed_scene(impl_->device, scene);
    impl_->triangle_count = uint32_t(scene.triangles.size());
    impl_->parallelogram_count = scene.triangles.parallelogram_count;
}

EmbreeBaseline::~EmbreeBaseline() {
    rtcReleaseScene(impl_->scene);
    rtcReleaseDevice(impl_->device);
}

void EmbreeBaseline::closest(EmbreeApi api, const RayView& rays, const HitView& hits, bool coherent) const {
    if (api == EmbreeApi::packet8) return impl_->closest_packets<8>(rays, hits, coherent);
    if (api == EmbreeApi::packet16) return impl_->closest_packets<16>(rays, hits, coherent);
    RTCIntersectContext context = context_for(coherent);
    for (uint32_t i = 0; i < rays.count; ++i) {
        RTCRayHit r;
        r.ray.org_x = rays.ox[i], r.ray.org_y = rays.oy[i], r.ray.org_z = rays.oz[i];
        r.ray.dir_x = rays.dx[i], r.ray.dir_y = rays.dy[i], r.ray.dir_z = rays.dz[i];
        r.ray.tnear = 0.0f;
        r.ray.tfar = max_distance(rays, i);
        r.ray.time = 0.0f;
        r.ray.mask = ~0u;
        r.ray.id = i;
        r.ray.flags = 0;
        r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(impl_->scene, &context, &r);
        hits.prim[i] = impl_->our_prim(r.hit.geomID, r.hit.primID);
        hits.t[i] = hits.prim[i] != kNoHit ? r.ray.tfar : kInfinity;
        hits.u[i] = r.hit.u;
        hits.v[i] = r.hit.v;
    }
}

void EmbreeBaseline::any(EmbreeApi api, const RayView& rays, uint8_t* occluded, bool coherent) const {
    if (api == EmbreeApi::packet8) return impl_->any_packets<8>(rays, occluded, coherent);
    if (api == EmbreeApi::packet16) return impl_->any_packets<16>(rays, occluded, coherent);
    RTCIntersectContext context = context_for(coherent);
    for (uint32_t i = 0; i < rays.count; ++i) {
        RTCRay r;
        r.org_x = rays.ox[i], r.org_y = rays.oy[i], r.org_z = rays.oz[i];
        r.dir_x = rays.dx[i], r.dir_y = rays.dy[i], r.dir_z = rays.dz[i];
        r.tnear = 0.0f;
        r.tfar = max_distance(rays, i);
        r.time = 0.0f;
        r.mask = ~0u;
        r.id = i;
        r.flags = 0;
        rtcOccluded1(impl_->scene, &context, &r);
        occluded[i] = r.tfar < 0.0f;
    }
}


struct EmbreeSceneBuilder::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
};

EmbreeSceneBuilder::EmbreeSceneBuilder(int threads) : impl_(std::make_unique<Impl>()) { impl_->device = new_device(threads); }

EmbreeSceneBuilder::~EmbreeSceneBuilder() {
    release();
    rtcReleaseDevice(impl_->device);
}

void EmbreeSceneBuilder::build(const Scene& scene) {
    release();
    impl_->scene = new_committed_scene(impl_->device, scene);
}

void EmbreeSceneBuilder::release() {
    if (impl_->scene) rtcReleaseScene(impl_->scene);
    impl_->scene = nullptr;
}

}  // namespace wt::bench
