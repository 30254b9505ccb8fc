#include "engine/core/SceneKeywords.h"

namespace modeflow {

using keywords::Choices;
using keywords::keywordOf;

std::string_view sceneKeyword(ShapeKind kind) {
    return keywordOf(Choices<ShapeKind>(keywords::kShapeKinds), kind);
}
std::string_view sceneKeyword(CsgOp op) {
    return keywordOf(Choices<CsgOp>(keywords::kCsgOps), op);
}
std::string_view sceneKeyword(ScalarBoundary boundary) {
    return keywordOf(Choices<ScalarBoundary>(keywords::kScalarBoundaries), boundary);
}
std::string_view sceneKeyword(WallKind wall) {
    return keywordOf(Choices<WallKind>(keywords::kWalls), wall);
}
std::string_view sceneKeyword(BoundaryTreatment treatment) {
    return keywordOf(Choices<BoundaryTreatment>(keywords::kBoundaries), treatment);
}
std::string_view sceneKeyword(CoefficientStorage storage) {
    return keywordOf(Choices<CoefficientStorage>(keywords::kCoefficientStorages), storage);
}
std::string_view sceneKeyword(Integrator integrator) {
    return keywordOf(Choices<Integrator>(keywords::kIntegrators), integrator);
}
std::string_view sceneKeyword(InitialVelocity velocity) {
    return keywordOf(Choices<InitialVelocity>(keywords::kInitialVelocities), velocity);
}
std::string_view sceneKeyword(AdvectionScheme scheme) {
    return keywordOf(Choices<AdvectionScheme>(keywords::kAdvectionSchemes), scheme);
}

}  // namespace modeflow
