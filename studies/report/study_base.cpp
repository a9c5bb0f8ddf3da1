#include "report/study_base.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "analysis/fit_options.hpp"
#include "coarse/settings.hpp"
#include "config/yaml_node.hpp"
#include "core/error.hpp"
#include "measure/settings.hpp"
#include "packing/packing_profile.hpp"
#include "profile/profile.hpp"
#include "report/study_file.hpp"

namespace softpack {

const StudyBaseKind& study_base_kind(StudyBase base) {
  static const StudyBaseKind profile{StudyBase::profile,
                                     "a profile",
                                     {"packings", "normal", "tangential", "sliding", "averages", "fits"},
                                     {"tangential"},
                                     {{"packing", "packings"}, {"normal", "normal"}, {"tangential", "tangential"}, {"sliding", "sliding"}},
                                     true};
  static const StudyBaseKind coarse{StudyBase::coarse_grain,
                                    "the coarse-grain validation's settings",
                                    {"coarse-grain-runs"},
                                    {"coarse-grain-runs"},
                                    {{"medium", "media"}, {"resolved", "resolved"}, {"soft", "soft"}},
                                    false};
  return base == StudyBase::coarse_grain ? coarse : profile;
}

const StudyBaseKind& study_base_kind(const YAML::Node& yaml) {
  return study_base_kind(yaml.IsMap() && yaml.size() == 1 && yaml["coarse_grain"] ? StudyBase::coarse_grain : StudyBase::profile);
}

void place_setting_seeds(YAML::Node& file, StudyBase base, const std::string& setting, const std::string& description,
                         const std::vector<std::uint64_t>& seeds) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (std::uint64_t s : seeds) list.push_back(s);
  list.SetStyle(YAML::EmitterStyle::Flow);
  if (base == StudyBase::coarse_grain) {
    file["coarse_grain"]["seeds"] = list;  // (the section has no name or description)
    return;
  }
  file["profile"] = setting;
  file["description"] = description;
  file["seeds"] = list;
}

void check_setting_file(StudyBase base, const std::string& text, const std::string& name) {
  try {
    const ConfigNode p = ConfigNode::load_string(text, name);
    if (base == StudyBase::coarse_grain) {
      read_coarse_grain_settings(p);
      return;
    }
    parse_seeds(p);
    parse_packing(p);
    parse_measurement(p);
    fit::parse_fit_section(p);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    throw InputError(msg.rfind(name, 0) == 0 ? msg : name + ": " + msg);
  }
}

std::string setting_make_args(StudyBase base, const std::string& study_dir, const std::vector<std::string>& goals,
                              const std::string& reuse) {
  const std::string file = study_dir + "/profiles/@SETTING@.yaml";
  if (base == StudyBase::coarse_grain)
    return fmt::format("COARSE_CONFIG={} COARSE_DIR={}/@SETTING@ {}", file, study_dir, fmt::join(goals, " "));
  return fmt::format("PROFILE=@SETTING@ PROFILE_FILE={} DATA={} {} {}", file, study_dir, reuse, fmt::join(goals, " "));
}

std::vector<std::string> setting_stamps(StudyBase base, const ConfigNode& root, const std::string& release) {
  if (base == StudyBase::coarse_grain) {
    const CoarseStamps s = coarse_stamps(root, release);
    return {s.medium, s.resolved, s.soft};
  }
  std::vector<std::string> stamps;
  for (const auto& [stage, folder] : study_base_kind(StudyBase::profile).shared) {
    try {
      stamps.push_back(profile_stamp(root, stage, release));
    } catch (const InputError&) {
      stamps.emplace_back();  // a stage the profile has not (sliding): nothing to share
    }
  }
  return stamps;
}

std::vector<std::uint64_t> setting_file_seeds(StudyBase base, const std::string& path) {
  const ConfigNode root = ConfigNode::load_file(path);
  return base == StudyBase::coarse_grain ? parse_seeds(root.at("coarse_grain")) : parse_seeds(root);
}

std::vector<SharedStage> shareable_stages(StudyBase base, const std::string& study_dir, const std::string& setting,
                                          const std::vector<std::string>& earlier, const std::string& release) {
  namespace fs = std::filesystem;
  const auto file = [&](const std::string& s) { return fmt::format("{}/profiles/{}.yaml", study_dir, s); };
  const std::vector<std::string> own = setting_stamps(base, ConfigNode::load_file(file(setting)), release);
  const std::vector<std::uint64_t> seeds = setting_file_seeds(base, file(setting));
  const auto& shared = study_base_kind(base).shared;
  std::vector<SharedStage> out;
  for (std::size_t k = 0; k < shared.size(); ++k) {
    const auto& [stage, folder] = shared[k];
    if (own[k].empty() || fs::exists(fmt::format("{}/{}/{}", study_dir, setting, folder))) continue;
    for (const std::string& d : earlier) {
      const std::string stamp_file = fmt::format("{}/{}/stamps/{}.hash", study_dir, d, stage);
      if (d == setting || !fs::is_directory(fmt::format("{}/{}/{}", study_dir, d, folder)) || !fs::is_regular_file(stamp_file)) continue;
      std::ifstream in(stamp_file);
      std::string theirs;
      in >> theirs;
      if (theirs != own[k]) continue;
      const std::vector<std::uint64_t> their_seeds = setting_file_seeds(base, file(d));
      if (!std::all_of(seeds.begin(), seeds.end(),
                       [&](std::uint64_t s) { return std::find(their_seeds.begin(), their_seeds.end(), s) != their_seeds.end(); }))
        continue;
      out.push_back({stage, folder, d});
      break;
    }
  }
  return out;
}

std::vector<std::string> stale_settings(const Study& study, const std::string& study_dir, const std::string& release) {
  std::vector<std::string> stale;
  std::vector<const StudySetting*> all{&study.reference};
  for (const StudySetting& s : study.settings) all.push_back(&s);
  const auto& shared = study_base_kind(study.base_kind).shared;
  for (const StudySetting* s : all) {
    if (!s->runs()) continue;
    const std::vector<std::string> now =
        setting_stamps(study.base_kind, ConfigNode::load_string(setting_profile_text(study, *s), study.path + " (setting " + s->name + ")"), release);
    for (std::size_t k = 0; k < shared.size(); ++k) {
      std::ifstream in(fmt::format("{}/{}/stamps/{}.hash", study_dir, s->name, shared[k].first));
      std::string recorded;
      if (in >> recorded && recorded != now[k]) {
        stale.push_back(s->name);
        break;
      }
    }
  }
  return stale;
}

}  // namespace softpack
