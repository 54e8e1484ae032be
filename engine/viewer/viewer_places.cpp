#include "engine/viewer/viewer_places.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <fmt/format.h>

namespace globe {

namespace {

// The characters a place is written with; others (the G that opened the line) are dropped.
bool placeCharacter(int c) {
  return (c >= '0' && c <= '9') || c == '.' || c == ',' || c == '-' || c == '+' || c == ' ';
}

std::string describe(const GeodeticPose& p) {
  return fmt::format("{:.5f}, {:.5f}, {:.1f} m above the ground", p.latitude_deg, p.longitude_deg, p.height_m);
}

}  // namespace

ViewerPlaces::ViewerPlaces(std::string bookmarksPath, std::vector<Bookmark> bookmarks)
    : path_(std::move(bookmarksPath)), bookmarks_(std::move(bookmarks)) {}

bool ViewerPlaces::handleTyping(const InputEvent& e) {
  if (e.type == InputEvent::Type::kChar) {
    if (placeCharacter(e.code) && typed_.size() < kMaxTyped) typed_ += char(e.code);
    return true;
  }
  if (e.type != InputEvent::Type::kKey || !e.down) return false;
  if (e.code == GLFW_KEY_BACKSPACE && !typed_.empty()) typed_.pop_back();
  if (e.code == GLFW_KEY_ENTER || e.code == GLFW_KEY_KP_ENTER) submitted_ = typed_;
  if (e.code == GLFW_KEY_ENTER || e.code == GLFW_KEY_KP_ENTER || e.code == GLFW_KEY_ESCAPE) typing_ = false;
  return true;
}

bool ViewerPlaces::handle(const InputEvent& e) {
  if (typing_) return handleTyping(e);
  if (e.type != InputEvent::Type::kKey || !e.down) return false;
  if (e.code == GLFW_KEY_G) {
    typing_ = true;
    typed_.clear();
  } else if (e.code == GLFW_KEY_M) {
    markWanted_ = true;
  } else if (e.code >= GLFW_KEY_1 && e.code <= GLFW_KEY_9) {
    wanted_ = std::size_t(e.code - GLFW_KEY_1);
  } else {
    return false;
  }
  return true;
}

std::optional<GeodeticPose> ViewerPlaces::goTo(const GeodeticPose& current, std::string& message) {
  const std::string text = *submitted_;
  submitted_.reset();
  auto pose = parseGoTo(text, current);
  if (!pose) {
    message = pose.error().format();
    return std::nullopt;
  }
  message = "went to " + describe(*pose);
  return *pose;
}

void ViewerPlaces::mark(const GeodeticPose& current, std::string& message) {
  markWanted_ = false;
  std::vector<Bookmark> next = bookmarks_;
  next.push_back({current, "bookmark " + std::to_string(next.size() + 1)});
  if (Status st = saveBookmarks(path_, next); !st) {
    message = "bookmark not saved: " + st.error().format();
    return;
  }
  bookmarks_ = std::move(next);
  message = fmt::format("saved bookmark {} ({}) to {}", bookmarks_.size(), describe(current), path_);
}

std::optional<GeodeticPose> ViewerPlaces::apply(const GeodeticPose& current, std::string& message) {
  if (markWanted_) mark(current, message);
  if (submitted_) return goTo(current, message);
  if (!wanted_) return std::nullopt;
  const std::size_t index = *wanted_;
  wanted_.reset();
  if (index >= bookmarks_.size()) {
    message = fmt::format("no bookmark {} in {} ({} saved; M saves the view)", index + 1, path_, bookmarks_.size());
    return std::nullopt;
  }
  message = fmt::format("bookmark {}: {}", index + 1, describe(bookmarks_[index].pose));
  return bookmarks_[index].pose;
}

}  // namespace globe
