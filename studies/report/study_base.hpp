// What a study's base is (issue 30, docs/studies.md): a profile of the paper's measurement
// (experiments/<profile>.yaml; the profile DAG runs a setting: workflow/stamps.mk ... analysis.mk)
// or the coarse-grain validation's settings (a file whose one key is `coarse_grain`,
// experiments/coarse-grain.yaml; workflow/coarse.mk runs a setting's media and runs). Everything
// that differs between the two is here, once: where a setting's seeds go in its file, how the file
// is checked, the make goals a setting may run and the make variables that run it, and its stages'
// folders and stamps (what share_stages compares). The rest of the study pattern is the same.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace softpack {

class ConfigNode;
struct Study;

enum class StudyBase { profile, coarse_grain };

struct StudyBaseKind {
  StudyBase base;
  std::string name;                         ///< as the messages say it
  std::vector<std::string> goals;           ///< the make goals a study's `stages` may name
  std::vector<std::string> default_goals;   ///< without `stages`
  /// A stage whose results a setting may share with an earlier one, and the folder they are in
  /// (<study>/<setting>/<folder>/, its stamp <study>/<setting>/stamps/<stage>.hash).
  std::vector<std::pair<std::string, std::string>> shared;
  bool archive = false;                     ///< may name an archive of a profile's results
};

const StudyBaseKind& study_base_kind(StudyBase base);
/// The kind of the base `yaml` (read from `path`): a map with the one key `coarse_grain` is the
/// coarse-grain validation's, any other a profile's.
const StudyBaseKind& study_base_kind(const YAML::Node& yaml);

/// The file of a setting: its seeds put where the base kind keeps them (a profile's `seeds`, also
/// its `profile` name and a description; `coarse_grain.seeds`).
void place_setting_seeds(YAML::Node& file, StudyBase base, const std::string& setting, const std::string& description,
                         const std::vector<std::uint64_t>& seeds);

/// Checks a setting's generated file as its stages read it; InputError naming `name` and the key.
void check_setting_file(StudyBase base, const std::string& text, const std::string& name);

/// The make arguments that run a setting's `goals` in `study_dir`, with `@SETTING@` where its name
/// goes (workflow/studies.mk substitutes it); `reuse`: FROM_SCRATCH=1 or ARCHIVE=... (profiles).
std::string setting_make_args(StudyBase base, const std::string& study_dir, const std::vector<std::string>& goals,
                              const std::string& reuse);

/// The stamp of each shared stage of a setting's file (workflow/stamps.mk and coarse.mk write the
/// same ones), in the order of StudyBaseKind::shared ("" for a stage it has not); and its seeds.
std::vector<std::string> setting_stamps(StudyBase base, const ConfigNode& file, const std::string& release);
std::vector<std::uint64_t> setting_file_seeds(StudyBase base, const std::string& path);

/// A stage of `setting` that is shared with the `earlier` setting's (workflow/studies.mk links it).
struct SharedStage {
  std::string stage, folder, earlier;
};
/// The stages `setting` of the study in `study_dir` (its files in profiles/<setting>.yaml) shares:
/// it has no folder of that stage yet, and an earlier setting (in `earlier`'s order, the first that
/// fits) has that folder, a stamp file equal to the setting's stamp of the stage (stamps cover
/// every section upstream), and every seed of the setting (results are per seed).
std::vector<SharedStage> shareable_stages(StudyBase base, const std::string& study_dir, const std::string& setting,
                                          const std::vector<std::string>& earlier, const std::string& release);

/// The running settings of `study` whose results in `study_dir` are of another configuration than
/// their file now: a stamp file of one of their stages there holds another stamp (a setting edited
/// since, and not rerun: make NAME SETTINGS=...). A stage without a stamp file is not judged.
std::vector<std::string> stale_settings(const Study& study, const std::string& study_dir, const std::string& release);

}  // namespace softpack
