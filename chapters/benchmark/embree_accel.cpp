// Embree 3 behind the kit's scene query (embree_accel.hpp). Compiled only when CMake finds Embree.
#include "benchmark/embree_accel.hpp"

#include "common/error.hpp"
#include "common/stats.hpp"

#include <embree3/rtcore.h>

#include <atomic>
#include <limits>
#include <string>

namespace rt::bench {

namespace {

// Embree's geometry numbers: one geometry per kind of object.
constexpr unsigned sphere_geometry = 0, triangle_geometry = 1, cone_geometry = 2;

// The bytes Embree holds, by its memory monitor (called before and after each allocation).
bool monitor(void* user, ssize_t bytes, bool post)
{
    if (!post)
        static_cast<std::atomic<long long>*>(user)->fetch_add(bytes);
    return true;
}

}  // namespace

bool have_embree() { return true; }

struct EmbreeAccel::State {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    Objects objects;  // for the cones' callbacks
    std::atomic<long long> bytes{0};
    long long geometry_bytes = 0;
    double build_seconds = 0.0;
};

namespace {

void cone_bounds(const RTCBoundsFunctionArguments* args)
{
    const Objects& o = *static_cast<const Objects*>(args->geometryUserPtr);
    const Bounds b = o.bounds(o.first(ObjectKind::cone) + static_cast<int>(args->primID));
    *args->bounds_o = {b.min.x, b.min.y, b.min.z, 0.0f, b.max.x, b.max.y, b.max.z, 0.0f};
}

Ray ray_of(RTCRayN* ray, unsigned n)
{
    return {{RTCRayN_org_x(ray, n, 0), RTCRayN_org_y(ray, n, 0), RTCRayN_org_z(ray, n, 0)},
            {RTCRayN_dir_x(ray, n, 0), RTCRayN_dir_y(ray, n, 0), RTCRayN_dir_z(ray, n, 0)}};
}

void cone_intersect(const RTCIntersectFunctionNArguments* args)
{
    if (!args->valid[0])
        return;
    const Objects& o = *static_cast<const Objects*>(args->geometryUserPtr);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    ObjectHit h;
    const int k = o.first(ObjectKind::cone) + static_cast<int>(args->primID);
    if (!o.intersect(k, ray_of(ray, args->N), {RTCRayN_tnear(ray, args->N, 0), RTCRayN_tfar(ray, args->N, 0)}, h))
        return;
    RTCRayN_tfar(ray, args->N, 0) = h.t;
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    RTCHitN_geomID(hit, args->N, 0) = args->geomID;
    RTCHitN_primID(hit, args->N, 0) = args->primID;
    RTCHitN_instID(hit, args->N, 0, 0) = args->context->instID[0];
}

void cone_occluded(const RTCOccludedFunctionNArguments* args)
{
    if (!args->valid[0])
        return;
    const Objects& o = *static_cast<const Objects*>(args->geometryUserPtr);
    ObjectHit h;
    const int k = o.first(ObjectKind::cone) + static_cast<int>(args->primID);
    if (o.intersect(k, ray_of(args->ray, args->N), {RTCRayN_tnear(args->ray, args->N, 0), RTCRayN_tfar(args->ray, args->N, 0)}, h))
        RTCRayN_tfar(args->ray, args->N, 0) = -std::numeric_limits<float>::infinity();
}

}  // namespace

EmbreeAccel::EmbreeAccel(const Objects& objects, EmbreeQuality quality, int threads) : state_(std::make_unique<State>())
{
    State& s = *state_;
    s.objects = objects;
    const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
    s.device = rtcNewDevice(config.c_str());
    if (!s.device)
        throw InputError("Embree could not start (rtcNewDevice failed)");
    rtcSetDeviceMemoryMonitorFunction(s.device, monitor, &s.bytes);
    s.scene = rtcNewScene(s.device);
    rtcSetSceneBuildQuality(s.scene, quality == EmbreeQuality::high ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);

    if (objects.sphere_count > 0) {
        RTCGeometry g = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), static_cast<size_t>(objects.sphere_count)));
        for (int k = 0; k < objects.sphere_count; ++k) {
            const Sphere& sp = objects.spheres[k];
            v[4 * k] = sp.centre.x;
            v[4 * k + 1] = sp.centre.y;
            v[4 * k + 2] = sp.centre.z;
            v[4 * k + 3] = sp.radius;
        }
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s.scene, g, sphere_geometry);
        rtcReleaseGeometry(g);
    }
    if (objects.triangle_count > 0) {
        const auto n = static_cast<size_t>(objects.triangle_count);
        RTCGeometry g = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), 3 * n));
        auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                     3 * sizeof(unsigned), n));
        for (size_t k = 0; k < n; ++k) {
            const Triangle& t = objects.triangles[k];
            const point3 corners[3] = {t.a, t.b, t.c};
            for (int c = 0; c < 3; ++c) {
                for (int axis = 0; axis < 3; ++axis)
                    v[9 * k + 3 * c + axis] = corners[c][axis];
                index[3 * k + c] = static_cast<unsigned>(3 * k + c);
            }
        }
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s.scene, g, triangle_geometry);
        rtcReleaseGeometry(g);
    }
    if (objects.cone_count > 0) {
        RTCGeometry g = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(objects.cone_count));
        rtcSetGeometryUserData(g, &s.objects);
        rtcSetGeometryBoundsFunction(g, cone_bounds, nullptr);
        rtcSetGeometryIntersectFunction(g, cone_intersect);
        rtcSetGeometryOccludedFunction(g, cone_occluded);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s.scene, g, cone_geometry);
        rtcReleaseGeometry(g);
    }
    // The geometry's own copy is not the structure: only what the build adds counts.
    s.geometry_bytes = s.bytes.load();
    const Timer timer;
    rtcCommitScene(s.scene);
    s.build_seconds = timer.seconds();
    if (rtcGetDeviceError(s.device) != RTC_ERROR_NONE)
        throw InputError("Embree could not build the scene (rtcCommitScene failed)");
}

EmbreeAccel::~EmbreeAccel()
{
    if (state_->scene)
        rtcReleaseScene(state_->scene);
    if (state_->device)
        rtcReleaseDevice(state_->device);
}

bool EmbreeAccel::closest(const Ray& ray, Interval range, const Objects& objects, ObjectHit& hit) const
{
    alignas(16) RTCRayHit rh{};
    rh.ray = {ray.origin.x, ray.origin.y, ray.origin.z, range.min, ray.dir.x, ray.dir.y, ray.dir.z, 0.0f,
              range.max, ~0u, 0u, 0u};
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(state_->scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return false;
    const int prim = static_cast<int>(rh.hit.primID);
    hit.t = rh.ray.tfar;
    const ObjectKind kind = rh.hit.geomID == sphere_geometry     ? ObjectKind::sphere
                            : rh.hit.geomID == triangle_geometry ? ObjectKind::triangle
                                                                 : ObjectKind::cone;
    hit.object = objects.first(kind) + prim;
    return true;
}

bool EmbreeAccel::any(const Ray& ray, Interval range, const Objects&) const
{
    alignas(16) RTCRay r{ray.origin.x, ray.origin.y, ray.origin.z, range.min, ray.dir.x, ray.dir.y, ray.dir.z, 0.0f,
                         range.max, ~0u, 0u, 0u};
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(state_->scene, &context, &r);
    return r.tfar == -std::numeric_limits<float>::infinity();
}

std::size_t EmbreeAccel::bytes() const
{
    return static_cast<std::size_t>(std::max(0LL, state_->bytes.load() - state_->geometry_bytes));
}

double EmbreeAccel::build_seconds() const { return state_->build_seconds; }

}  // namespace rt::bench
