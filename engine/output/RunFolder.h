#pragma once
/// @file RunFolder.h
/// The folder a run writes its frames into, held for the whole run:
/// - one run at a time per scene name in a folder: an advisory lock (flock) on a hidden file,
///   which the kernel releases when the process ends however it ends, so a crash never leaves a
///   stale lock and a second run into the same folder is refused at once instead of interleaving
///   its frames with the first's;
/// - temporaries of runs that were killed while writing (NAME.tmp-PID whose process is gone) are
///   swept away when the folder is taken;
/// - a fresh run first removes the earlier run's files of its scene (frames, pictures, contact
///   sheet, checkpoint), so a shorter rerun leaves none of the old run's later frames behind.

#include <filesystem>
#include <string>

namespace modeflow {

class RunFolder {
public:
    /// Creates `folder` if needed and takes it for `sceneName`.
    /// @throw modeflow::Error naming the folder when it cannot be created or locked, or when
    ///        another run holds it (with that run's process id).
    RunFolder(std::filesystem::path folder, std::string sceneName);
    ~RunFolder();
    RunFolder(const RunFolder&) = delete;
    RunFolder& operator=(const RunFolder&) = delete;

    const std::filesystem::path& path() const { return mFolder; }
    /// OUT/NAME.resume.
    std::filesystem::path checkpointPath() const;
    /// OUT/.NAME.lock, the file the lock is held on.
    static std::filesystem::path lockPath(const std::filesystem::path& folder,
                                          const std::string& sceneName);

    /// Temporaries of gone processes removed when the folder was taken.
    int staleTemporariesRemoved() const { return mStaleRemoved; }
    /// Removes the files an earlier run of this scene left here (NAME_0001.vdb or .ply,
    /// NAME_particles_0001.ply, NAME_0001.png, NAME_contact.png, NAME.resume; other scenes' files
    /// stay) and returns how many.
    int removeEarlierRun() const;

private:
    std::filesystem::path mFolder;
    std::string mScene;
    int mLock = -1;
    int mStaleRemoved = 0;
};

}  // namespace modeflow
