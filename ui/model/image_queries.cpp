#include "model/image_queries.h"

#include "render/frame_setup.h"

namespace trazo {

namespace {

// The kernels' camera (makeFrameParams, generateCameraRay) for this size, through image positions (x, y).
std::vector<RayQuery> cameraRays(const Scene& scene, uint32_t width, uint32_t height, const std::vector<float>& xy) {
    const CameraFrame camera = makeFrameParams(scene, width, height, 0).camera;
    std::vector<RayQuery> queries(xy.size() / 2);
    for (size_t i = 0; i < queries.size(); ++i)
        queries[i] = RayQuery{generateCameraRay(camera, xy[2 * i], xy[2 * i + 1]), INFINITY};
    return queries;
}

}  // namespace

std::optional<ObjectId> objectOfAnswer(const std::vector<ObjectId>& sources, int32_t answer) {
    if (isAreaLightAnswer(answer)) return ObjectId{ObjectId::Kind::AreaLight, areaLightOfAnswer(answer)};
    if (answer < 0 || size_t(answer) >= sources.size()) return std::nullopt;
    return sources[size_t(answer)];
}

std::optional<PickHit> pickObject(Backend& backend, const Scene& scene, const std::vector<ObjectId>& sources,
                                  uint32_t width, uint32_t height, float x, float y) {
    const std::vector<RayQuery> queries = cameraRays(scene, width, height, {x, y});
    std::vector<RayAnswer> answers;
    backend.traceRays(queries, RayQueryKind::Object, answers);
    const std::optional<ObjectId> object = objectOfAnswer(sources, answers[0].object);
    if (!object) return std::nullopt;
    return PickHit{*object, answers[0].t, pointAt(queries[0].ray, answers[0].t)};
}

std::vector<int32_t> objectIdsOf(Backend& backend, const Scene& scene, uint32_t width, uint32_t height) {
    std::vector<float> xy;
    xy.reserve(size_t(width) * height * 2);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            xy.push_back(float(x) + 0.5f);
            xy.push_back(float(y) + 0.5f);
        }
    }
    std::vector<RayAnswer> answers;
    backend.traceRays(cameraRays(scene, width, height, xy), RayQueryKind::Object, answers);
    std::vector<int32_t> ids(answers.size());
    for (size_t i = 0; i < answers.size(); ++i) ids[i] = answers[i].object;
    return ids;
}

std::vector<uint8_t> selectionMaskOf(const std::vector<ObjectId>& sources, const std::vector<int32_t>& ids,
                                     const ObjectId& selected) {
    // The one answer that stands for `selected` (an object that draws nothing has none: an empty mask).
    int32_t want = kMissAnswer;
    if (selected.kind == ObjectId::Kind::AreaLight) want = areaLightAnswer(selected.index);
    for (size_t i = 0; i < sources.size() && !selected.isLight(); ++i)
        if (sources[i] == selected) want = int32_t(i);
    std::vector<uint8_t> mask(ids.size(), 0);
    if (want == kMissAnswer) return mask;
    for (size_t i = 0; i < ids.size(); ++i) mask[i] = ids[i] == want ? 1 : 0;
    return mask;
}

}  // namespace trazo
