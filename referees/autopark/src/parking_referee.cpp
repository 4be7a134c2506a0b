#include "aula/autopark/parking_referee.hpp"

#include <aula/geometry/angles.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aula::autopark {
namespace {

double angleScore(double yaw_error_deg) {
  const double e = std::abs(yaw_error_deg);
  return e <= 15.0 ? 100.0 : e <= 45.0 ? 50.0 : 0.0;
}

}  // namespace

ParkingRefereeSettings parkingRefereeSettings(const config::Config& cfg) {
  ParkingRefereeSettings s;
  s.rubric = cfg.getString("Autopark.Referee.Rubric");
  s.timeout_s = cfg.getDouble("Autopark.Referee.Timeout");
  s.still_hold_s = cfg.getDouble("Autopark.Referee.StillHold");
  s.full_time_s = cfg.getDouble("Autopark.Referee.FullMarkTime");
  s.gaps_relative_to_slot = cfg.getString("Autopark.Referee.GapRule") == "slot";
  const auto fractions = cfg.getDoubleList("Autopark.Referee.SlotGapFractions");
  const auto gaps = cfg.getDoubleList("Autopark.Referee.GapBands");
  const auto curb = cfg.getDoubleList("Autopark.Referee.CurbBands");
  // The ranges of each number are declared (aula_settings); their order is checked here.
  auto bad = [&](const std::string& key, const std::string& what) {
    throw config::ConfigError(cfg.origin(key) + ": " + key + " = " + cfg.getString(key) + ": " + what);
  };
  if (!(fractions[0] <= fractions[1])) bad("Autopark.Referee.SlotGapFractions", "expected half <= full (fractions of the ideal gap)");
  if (!(gaps[0] <= gaps[1] && gaps[1] < gaps[2])) bad("Autopark.Referee.GapBands", "expected half_from <= full_from < full_to (m)");
  if (!(curb[0] > 0 && curb[0] <= curb[1])) bad("Autopark.Referee.CurbBands", "expected 0 < full <= half (m)");
  s.slot_gap_half_fraction = fractions[0];
  s.slot_gap_full_fraction = fractions[1];
  s.gap_half_from_m = gaps[0];
  s.gap_full_from_m = gaps[1];
  s.gap_full_to_m = gaps[2];
  s.curb_full_m = curb[0];
  s.curb_half_m = curb[1];
  s.thesis_scale = cfg.getString("Autopark.Referee.Scale") == "thesis";
  s.not_parked_mark = cfg.getDouble("Autopark.Referee.NotParkedMark");
  const auto cost = cfg.getDoubleList("Autopark.Referee.ContactCost");
  s.contact_share = cost[0];
  s.contact_share_per_s = cost[1];
  s.contact_share_per_cm = cost[2];
  return s;
}

double gapScore(double gap_m, double ideal_gap_m, const ParkingRefereeSettings& s) {
  if (s.gaps_relative_to_slot) {
    if (!(ideal_gap_m > 0) || !(gap_m > 0)) return 0.0;  // no room in the slot, or touching
    return gap_m >= s.slot_gap_full_fraction * ideal_gap_m ? 100.0 : gap_m >= s.slot_gap_half_fraction * ideal_gap_m ? 50.0 : 0.0;
  }
  if (gap_m >= s.gap_full_from_m && gap_m < s.gap_full_to_m) return 100.0;
  if (gap_m >= s.gap_half_from_m && gap_m < s.gap_full_from_m) return 50.0;
  return 0.0;
}

std::string gapRuleText(const ParkingRefereeSettings& s) {
  char gaps[128], text[256];
  if (s.gaps_relative_to_slot) {
    std::snprintf(gaps, sizeof gaps, "gaps of at least %.0f %% of a centred car's (half from %.0f %%)",
                  100 * s.slot_gap_full_fraction, 100 * s.slot_gap_half_fraction);
  } else {
    std::snprintf(gaps, sizeof gaps, "gaps in [%.3g, %.3g) m (half from %.3g m)", s.gap_full_from_m, s.gap_full_to_m,
                  s.gap_half_from_m);
  }
  std::snprintf(text, sizeof text, "full marks for %s, the curb within %.3g m, parked in under %.4g s", gaps,
                s.curb_full_m, s.full_time_s);
  return text;
}

double curbScore(double gap_m, const ParkingRefereeSettings& s) {
  if (gap_m < 0) return 0.0;  // over the curb
  return gap_m <= s.curb_full_m ? 100.0 : gap_m < s.curb_half_m ? 50.0 : 0.0;
}

const char* caseName(ParkingCase c) {
  switch (c) {
    case ParkingCase::Parked: return "parked";
    case ParkingCase::ParkedElsewhere: return "parked_elsewhere";
    case ParkingCase::DroveOff: return "drove_off";
    case ParkingCase::StayedStill: return "stayed_still";
    case ParkingCase::GaveUp: break;
  }
  return "gave_up";
}

std::string caseText(ParkingCase c) {
  switch (c) {
    case ParkingCase::Parked: return "parked";
    case ParkingCase::ParkedElsewhere: return "NOT parked: stopped at the curb outside the slot";
    case ParkingCase::DroveOff: return "NOT parked: drove off the street";
    case ParkingCase::StayedStill: return "NOT parked: stayed where it started";
    case ParkingCase::GaveUp: break;
  }
  return "NOT parked: gave up or stopped elsewhere";
}

double contactCost(const ParkingContacts& c, const ParkingRefereeSettings& s) {
  const double cost = c.count * s.contact_share + c.duration_s * s.contact_share_per_s + 100 * c.depth_m * s.contact_share_per_cm;
  return std::clamp(cost, 0.0, 1.0);
}

std::string markFormula(const ParkingScores& s, ParkingCase c, double contact_cost, const ParkingRefereeSettings& settings) {
  char text[256];
  if (settings.thesis_scale) {
    std::snprintf(text, sizeof text, "0.025 x (angle %.0f + time %.0f + distances %.1f + collisions %.0f)", s.angle, s.time,
                  s.distance, s.collision);
  } else if (c != ParkingCase::Parked) {
    std::snprintf(text, sizeof text, "not parked %.2f x (1 - contacts %.2f)", settings.not_parked_mark, contact_cost);
  } else {
    std::snprintf(text, sizeof text, "0.025 x (angle %.0f + time %.0f + distances %.1f + 100) x (1 - contacts %.2f)", s.angle,
                  s.time, s.distance, contact_cost);
  }
  return text;
}

std::string distancesText(const ParkingMeasures& m, ParkingCase c, const ParkingRefereeSettings& s) {
  char text[200];
  if (!s.thesis_scale && c != ParkingCase::Parked) {
    std::snprintf(text, sizeof text, "not graded: not parked (gaps front %.2f m, rear %.2f m, curb %.2f m)", m.front_gap_m,
                  m.rear_gap_m, m.curb_gap_m);
  } else if (!m.inside_slot) {
    std::snprintf(text, sizeof text, "not graded: not inside the slot");
  } else {
    std::snprintf(text, sizeof text, "front %.2f m (%.0f), rear %.2f m (%.0f), curb %.2f m (%.0f) of 100 each; a centred car: %.2f m",
                  m.front_gap_m, gapScore(m.front_gap_m, m.ideal_gap_m, s), m.rear_gap_m, gapScore(m.rear_gap_m, m.ideal_gap_m, s),
                  m.curb_gap_m, curbScore(m.curb_gap_m, s), m.ideal_gap_m);
  }
  return text;
}

std::vector<referee::MarkTerm> parkingMarkTerms(const ParkingMeasures& m, ParkingCase c, double park_time_s,
                                                const ParkingContacts& contacts, const ParkingRefereeSettings& s) {
  const ParkingScores scores = scoreParking(m, c, park_time_s, contacts, s);
  const bool parked = c == ParkingCase::Parked;
  const bool graded = s.thesis_scale || parked;
  char angle[96], time[96], contact_text[160];
  if (!graded) {
    std::snprintf(angle, sizeof angle, "not graded: not parked (%.1f deg to the curb)", m.yaw_error_deg);
  } else if (!m.inside_slot) {
    std::snprintf(angle, sizeof angle, "not graded: not inside the slot (%.1f deg to the curb)", m.yaw_error_deg);
  } else {
    std::snprintf(angle, sizeof angle, "%.1f deg to the curb", m.yaw_error_deg);
  }
  std::snprintf(time, sizeof time, "%s in %.1f s (full under %.4g s)", parked ? "parked" : "not parked", park_time_s, s.full_time_s);
  std::snprintf(contact_text, sizeof contact_text, "%lld collision(s), %.1f s in contact, %.1f mm deep", contacts.count,
                contacts.duration_s, 1e3 * contacts.depth_m);
  std::vector<referee::MarkTerm> rows = {{"angle", angle, 0.025 * scores.angle, 2.5},
                                         {"time", time, 0.025 * scores.time, 2.5},
                                         {"distances", distancesText(m, c, s), 0.025 * scores.distance, 2.5}};
  if (s.thesis_scale) {
    rows.push_back({"collisions", std::string(contact_text) + (contacts.count ? ": the term is lost" : ""), 0.025 * scores.collision, 2.5});
    return rows;
  }
  char rule[160];
  if (parked) {
    std::snprintf(rule, sizeof rule, "parked in the slot");
  } else {
    std::snprintf(rule, sizeof rule, "%s: the rubric gives %.2f, whatever the terms", caseText(c).c_str(), s.not_parked_mark);
  }
  rows.push_back({"parked", rule, parked ? 2.5 : s.not_parked_mark, 2.5});
  const double cost = contactCost(contacts, s);
  char factor[224];
  std::snprintf(factor, sizeof factor, "%s: the mark x (1 - cost %.2f)", contact_text, cost);
  referee::MarkTerm keep{"contacts", factor};
  keep.factor = 1.0 - cost;
  rows.push_back(keep);
  return rows;
}

ParkingScores scoreParking(const ParkingMeasures& m, ParkingCase c, double park_time_s, const ParkingContacts& contacts,
                           const ParkingRefereeSettings& s) {
  ParkingScores out;
  const bool parked = c == ParkingCase::Parked;
  const double keep = s.thesis_scale ? 1.0 : 1.0 - contactCost(contacts, s);
  if (!s.thesis_scale && !parked) {
    // Not parked is not parked, wherever the car ended: the terms grade nothing.
    out.collision = 100.0 * keep;
    out.mark = s.not_parked_mark * keep;
    return out;
  }
  // Angle and distances grade where the car is in the slot; outside it there is nothing to grade.
  if (m.inside_slot) {
    out.angle = angleScore(m.yaw_error_deg);
    out.distance =
        (gapScore(m.front_gap_m, m.ideal_gap_m, s) + gapScore(m.rear_gap_m, m.ideal_gap_m, s) + curbScore(m.curb_gap_m, s)) / 3.0;
  }
  if (parked) out.time = park_time_s < s.full_time_s ? 100.0 : 100.0 * s.full_time_s / park_time_s;
  if (s.thesis_scale) {
    out.collision = contacts.count == 0 ? 100.0 : 0.0;
    out.mark = 0.025 * (out.angle + out.time + out.distance + out.collision);
  } else {
    out.collision = 100.0 * keep;
    out.mark = 0.025 * (out.angle + out.time + out.distance + 100.0) * keep;
  }
  return out;
}

void ParkingReferee::start(int64_t utime) {
  if (start_utime_) return;  // the first Run starts the clock; a pause does not reset it
  start_utime_ = utime;
  if (have_pose_) start_xy_ = {x_, y_};
}

void ParkingReferee::onPose(int64_t utime, double x_m, double y_m, double yaw_rad) {
  if (have_pose_ && utime > last_pose_utime_) {
    const double dt = (utime - last_pose_utime_) / 1e6;
    speed_mps_ = std::hypot(x_m - x_, y_m - y_) / dt;
    // A car turning on the spot is not stationary: count its corners' speed.
    const double half_diagonal = std::hypot(scene_.car_length_m, scene_.car_width_m) / 2;
    speed_mps_ += std::abs(geometry::wrapAngle(yaw_rad - yaw_)) * half_diagonal / dt;
  }
  have_pose_ = true;
  last_pose_utime_ = utime;
  x_ = x_m;
  y_ = y_m;
  yaw_ = yaw_rad;
  if (finished_) return;
  measures_ = measureParking(scene_, x_, y_, yaw_);
  trail_.add(x_, y_);
  if (!started()) return;
  if (!start_xy_) start_xy_ = {x_, y_};
  if (std::hypot(x_ - start_xy_->first, y_ - start_xy_->second) > kMovedM) moved_ = true;
  if (offStreet(scene_, x_, y_)) left_street_ = true;
  if (in_contact_) contact_depth_m_ = std::max(contact_depth_m_, contactDepthM(scene_, x_, y_, yaw_));
}

void ParkingReferee::onContact(int64_t utime, bool pressed) {
  const bool counting = started() && !finished_;
  if (pressed && !in_contact_) {
    if (counting) ++contacts_.count;
    contact_since_utime_ = utime;
    contact_depth_m_ = have_pose_ ? contactDepthM(scene_, x_, y_, yaw_) : 0.0;
  } else if (!pressed && in_contact_ && counting) {
    endContact(utime);
  }
  in_contact_ = pressed;
}

void ParkingReferee::endContact(int64_t utime) {
  contact_us_ += utime - std::max(contact_since_utime_, *start_utime_);
  contacts_.depth_m += contact_depth_m_;
  deepest_m_ = std::max(deepest_m_, contact_depth_m_);
}

void ParkingReferee::onTick(int64_t utime) {
  now_utime_ = utime;
  if (!started() || finished_ || !have_pose_) return;
  const bool still = speed_mps_ < settings_.still_speed_mps && measures_.inside_slot;
  if (!still) {
    still_since_utime_.reset();
  } else if (!still_since_utime_) {
    still_since_utime_ = utime;
  }
  if (still_since_utime_ && (utime - *still_since_utime_) / 1e6 >= settings_.still_hold_s) {
    finished_ = parked_ = true;
    end_utime_ = std::max(*start_utime_, *still_since_utime_);  // parked when it stopped
  } else if ((utime - *start_utime_) / 1e6 >= settings_.timeout_s) {
    finished_ = true;
    end_utime_ = utime;
  }
  if (finished_ && in_contact_) endContact(utime);
}

double ParkingReferee::elapsedS() const {
  if (!start_utime_) return 0.0;
  return ((end_utime_ ? *end_utime_ : now_utime_) - *start_utime_) / 1e6;
}

double ParkingReferee::contactS() const {
  int64_t us = contact_us_;
  if (in_contact_ && started() && !finished_) us += now_utime_ - std::max(contact_since_utime_, *start_utime_);
  return us / 1e6;
}

ParkingContacts ParkingReferee::contacts() const {
  ParkingContacts out = contacts_;
  out.duration_s = contactS();
  if (in_contact_ && started() && !finished_) out.depth_m += contact_depth_m_;
  return out;
}

ParkingCase ParkingReferee::parkingCase() const {
  if (parked_) return ParkingCase::Parked;
  if (left_street_) return ParkingCase::DroveOff;
  if (!moved_) return ParkingCase::StayedStill;
  if (parkedElsewhere(scene_, measures_, y_) && speed_mps_ < settings_.still_speed_mps) return ParkingCase::ParkedElsewhere;
  return ParkingCase::GaveUp;
}

ParkingScores ParkingReferee::scores() const {
  return scoreParking(measures_, parkingCase(), elapsedS(), contacts(), settings_);
}

}  // namespace aula::autopark
