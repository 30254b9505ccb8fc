#include "engine/run/GridFrames.h"

#include <span>
#include <utility>
#include <vector>

#include "engine/output/ParticleFrame.h"

namespace modeflow {

GridFrames::GridFrames(Simulator& simulator, const RunInputs& run, GridFrameFiles files)
    : mSimulator(simulator),
      mRun(run),
      mFiles(std::move(files)),
      mBasisGrid(MacGrid::fromSpec(run.cache.grid)) {
    if (mFiles.previews)
        mPreview = std::make_unique<FramePreview>(mSimulator.smokeGrid(), mRun.smokeMask,
                                                  mFiles.previewDevice);
}

VdbFrame gridVdbFrame(const Simulator& simulator, std::span<const std::uint8_t> fluidMask,
                      const MacGrid& basisGrid, const SmokeFields& smoke,
                      std::span<const double> faceVelocity, std::span<const double> faceMagnetic,
                      int frame, std::string sceneHash, bool halfFloat) {
    VdbFrame vdb;
    vdb.smokeGrid = simulator.smokeGrid();
    vdb.basisGrid = basisGrid;
    vdb.density = std::span<const double>(smoke.density);
    if (simulator.settings().simulatesTemperature())
        vdb.temperature = std::span<const double>(smoke.temperature);
    vdb.faceVelocity = faceVelocity;
    vdb.faceMagnetic = faceMagnetic;
    vdb.fluidMask = fluidMask;
    vdb.frame = frame;
    vdb.time = simulator.time();
    vdb.sceneHash = std::move(sceneHash);
    vdb.modeflowVersion = MODEFLOW_VERSION;
    vdb.options.halfFloat = halfFloat;
    return vdb;
}

std::filesystem::path GridFrames::frameFile(int frame) const {
    return mFiles.folder / frameFileName(mFiles.sceneName, frame);
}

Checkpoint GridFrames::writeFrame(int frame, const std::filesystem::path& picture,
                                  FrameProgress& bar) {
    const bool temperature = settings().simulatesTemperature();
    SmokeFields smoke = bar.timed("reading fields", [&] { return mSimulator.smoke(); });
    const std::vector<double> faceVelocity =
        bar.timed("reading fields", [&] { return mSimulator.faceVelocity(); });
    const std::vector<double> faceMagnetic =
        bar.timed("reading fields", [&] { return mSimulator.faceMagneticField(); });
    const VdbFrame vdb = gridVdbFrame(mSimulator, mRun.smokeMask, mBasisGrid, smoke, faceVelocity,
                                      faceMagnetic, frame, mFiles.sceneHash, mFiles.halfFloat);
    bar.timed("VDB files", [&] { writeVdbFrame(frameFile(frame), vdb); });
    Particles particles;
    if (!settings().particles.empty()) {
        particles = bar.timed("reading fields", [&] { return mSimulator.particles(); });
        const ParticleFrame points{particles.position, particles.velocity, frame, mSimulator.time(),
                                   mFiles.sceneHash};
        bar.timed("particle files", [&] {
            writeParticleFrame(mFiles.folder / particleFrameFileName(mFiles.sceneName, frame),
                               points);
        });
    }
    if (!picture.empty() && mPreview)
        bar.timed("previews", [&] { mPreview->write(picture, smoke, temperature, particles); });
    return {frame,
            mSimulator.time(),
            0,
            mSimulator.velocity(),
            mSimulator.magneticField(),
            mSimulator.carry(),
            std::move(smoke),
            std::move(particles)};
}

void GridFrames::restore(const Checkpoint& from) {
    mSimulator.restore(from.time, from.velocity, from.smoke);
    if (settings().mhd) mSimulator.setMagneticField(from.magnetic);
    mSimulator.setCarry(from.carry);
    mSimulator.setParticles(from.particles);
}

}  // namespace modeflow
