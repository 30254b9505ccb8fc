#include "engine/run/Backend.h"

#include <algorithm>
#include <cctype>

#include "engine/core/Error.h"
#include "engine/core/SceneSpec.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModalStepper.h"
#include "engine/device/Simulation.h"
#include "engine/device/SurfaceSimulation.h"
#include "engine/reference/ModalStepper.h"
#include "engine/reference/Simulation.h"
#include "engine/run/RunInputs.h"
#include "engine/simulation/WindTransport.h"
#include "engine/surface/SurfaceSimulation.h"

namespace modeflow {

BackendChoice parseDeviceOption(std::string_view value) {
    BackendChoice choice;
    if (value == "cpu") {
        choice.kind = BackendKind::CpuReference;
        return choice;
    }
    if (value == "vulkan") return choice;
    const bool digits =
        !value.empty() && value.size() < 6 &&
        std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); });
    if (!digits)
        throw Error("--device " + std::string(value) +
                    ": expected cpu, vulkan or a Vulkan device index (0, 1, ...)");
    choice.vulkan.deviceIndex = std::uint32_t(std::stoul(std::string(value)));
    return choice;
}

Backend::Backend(const BackendChoice& choice) : mKind(choice.kind) {
    if (mKind == BackendKind::Vulkan) {
        mOwnedContext = std::make_unique<vulkan::VulkanContext>(choice.vulkan);
        mContext = mOwnedContext.get();
    }
}

Backend::Backend(BackendKind kind, const vulkan::VulkanContext& context)
    : mKind(kind), mContext(&context) {}

Backend::~Backend() = default;

std::string Backend::describe() const {
    return mKind == BackendKind::Vulkan ? mContext->describe() : std::string();
}

void Backend::requireFits(const SceneSpec& scene) const {
    if (mKind != BackendKind::Vulkan) return;
    const CoefficientStorage storage = scene.basis.coefficients;
    const bool assembled = storage == CoefficientStorage::Dense ||
                           storage == CoefficientStorage::Sparse ||
                           (storage == CoefficientStorage::Auto && hasClosedFormVelocity(scene));
    if (assembled)
        device::DeviceCoefficients::requirePairSumsFit(*mContext, scene.basis.velocityCount());
}

std::unique_ptr<Simulator> Backend::makeSimulator(const RunInputs& run, bool stageTimes) const {
    if (run.cache.kind == BasisKind::Surface)
        throw Error(run.scene.name + ": a surface scene runs as a SurfaceSimulator");
    std::unique_ptr<Simulator> simulator;
    if (mKind == BackendKind::Vulkan)
        simulator = std::make_unique<device::Simulation>(*mContext, run.cache, *run.coefficients,
                                                         run.settings, run.smokeMask, stageTimes);
    else
        simulator = std::make_unique<reference::Simulation>(run.cache, *run.coefficients,
                                                            run.settings, run.smokeMask);
    simulator->setVelocity(run.initialVelocity);
    if (run.settings.mhd) simulator->setMagneticField(run.initialMagneticField);
    return simulator;
}

std::unique_ptr<ModalStepping> Backend::makeModalStepper(const RunInputs& run,
                                                         Integrator scheme) const {
    // A wind's advection of the modes is part of the dynamics on either backend.
    SimulationSettings settings = withWindTransport(run.settings, run.cache);
    settings.integrator = scheme;
    std::unique_ptr<ModalStepping> stepper;
    if (mKind == BackendKind::Vulkan) {
        auto device = std::make_unique<device::ModalStepper>(
            *mContext, *run.coefficients, device::modelOf(settings),
            device::DeviceStepSettings{scheme}, &run.cache);
        device->setVelocity(run.initialVelocity);
        if (settings.mhd) device->setMagneticField(run.initialMagneticField);
        stepper = std::move(device);
    } else {
        auto reference = std::make_unique<reference::ModalStepper>(*run.coefficients, settings);
        reference->setVelocity(run.initialVelocity);
        if (settings.mhd) reference->setMagneticField(run.initialMagneticField);
        stepper = std::move(reference);
    }
    return stepper;
}

std::unique_ptr<SurfaceSimulator> Backend::makeSurfaceSimulator(const RunInputs& run) const {
    if (run.cache.kind != BasisKind::Surface)
        throw Error(run.scene.name + ": a grid scene runs as a Simulator");
    if (mKind == BackendKind::Vulkan)
        return std::make_unique<device::SurfaceSimulation>(*mContext, run.cache, *run.coefficients,
                                                           run.settings, run.initialVelocity);
    return std::make_unique<SurfaceSimulation>(run.cache, *run.coefficients, run.settings,
                                               run.initialVelocity);
}

void Backend::requireCleanValidation() const {
    if (mContext && mContext->validationMessageCount() > 0)
        throw Error("the Vulkan validation layer reported " +
                    std::to_string(mContext->validationMessageCount()) +
                    " problems; the first: " + mContext->validationMessages().front());
}

}  // namespace modeflow
