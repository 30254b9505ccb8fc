#pragma once
/// @file Backend.h
/// The backend a command simulates on, chosen once from `--device`, opened before any
/// precompute (so a device index that is not there is refused at once), and the one factory of
/// what runs on it: a Simulator (`run`, `stir`, tests, benchmarks), a SurfaceSimulator (surface
/// scenes) or a ModalStepping (`modes`).
/// What each backend can do is BackendCapabilities' table.

#include <memory>
#include <string>
#include <string_view>

#include "engine/simulation/BackendCapabilities.h"
#include "engine/simulation/ModalStepping.h"
#include "engine/simulation/Simulator.h"
#include "engine/simulation/SurfaceSimulator.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow {

struct RunInputs;

struct BackendChoice {
    BackendKind kind = BackendKind::Vulkan;
    vulkan::VulkanContextOptions vulkan;  ///< the device (index), validation, ...
};

/// The help text of `--device`.
inline constexpr const char* kDeviceOptionHelp =
    "cpu (double-precision reference), vulkan (first suitable device) or a Vulkan device index";

/// `--device`: `cpu`, `vulkan` (the first suitable Vulkan device: discrete, else integrated,
/// else a CPU device such as lavapipe) or a Vulkan device index (`vulkaninfo --summary`).
/// @throw modeflow::Error naming the option for anything else.
BackendChoice parseDeviceOption(std::string_view value);

class Backend {
public:
    /// Opens the backend: for a Vulkan device, chooses it and creates its context.
    /// @throw modeflow::Error when no suitable device is there (naming why each was passed over).
    explicit Backend(const BackendChoice& choice);
    /// A backend on a Vulkan context made elsewhere (the stir window's, which also presents):
    /// the device itself, or the CPU reference beside it when `kind` says so. `context` must
    /// outlive the backend.
    Backend(BackendKind kind, const vulkan::VulkanContext& context);
    ~Backend();
    Backend(const Backend&) = delete;
    Backend& operator=(const Backend&) = delete;

    BackendKind kind() const { return mKind; }
    const BackendCapabilities& capabilities() const { return capabilitiesOf(mKind); }
    /// The device's context; null for the CPU reference opened by the first constructor.
    const vulkan::VulkanContext* vulkanContext() const { return mContext; }
    /// The chosen device and why the others were passed over (empty for the CPU reference).
    std::string describe() const;

    /// Refuses, before its cache is read or made, a run of `scene` this backend's device cannot
    /// hold: today the pair sums of an assembled tensor (dense or sparse coefficients asked for,
    /// or a closed-form basis, whose coefficients are always sparse) above the device's limit.
    /// The CPU reference refuses nothing here.
    /// @throw modeflow::Error as DeviceCoefficients::requirePairSumsFit.
    void requireFits(const SceneSpec& scene) const;

    /// A simulation of the prepared run, at its initial state. It keeps references into `run`,
    /// which must outlive it and stay where it is. `stageTimes`: time each stage (device only).
    /// @throw modeflow::Error for a surface scene (makeSurfaceSimulator), settings the model
    ///        refuses, or a device error.
    std::unique_ptr<Simulator> makeSimulator(const RunInputs& run, bool stageTimes = false) const;
    /// A surface scene's simulation of the prepared run, at its initial state, keeping
    /// references into `run` as makeSimulator's.
    /// @throw modeflow::Error for a grid scene, settings the model refuses, or a device error.
    std::unique_ptr<SurfaceSimulator> makeSurfaceSimulator(const RunInputs& run) const;
    /// The reduced dynamics of the prepared run alone, with `scheme`, at its initial state
    /// ([v; F] with MHD).
    std::unique_ptr<ModalStepping> makeModalStepper(const RunInputs& run, Integrator scheme) const;

    /// @throw modeflow::Error when the Vulkan validation layer (MODEFLOW_VULKAN_VALIDATION=1)
    /// reported problems on this backend's context, quoting the first.
    void requireCleanValidation() const;

private:
    BackendKind mKind;
    std::unique_ptr<vulkan::VulkanContext> mOwnedContext;
    const vulkan::VulkanContext* mContext = nullptr;
};

}  // namespace modeflow
