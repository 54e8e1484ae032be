// The viewer's places (issue 37 item 4): the go-to line (G), bookmarks saved to a file (M) and
// recalled (1-9), and the TEXT event of input scripts that types into the go-to line.
#include "engine/viewer/viewer_places.h"
#include "engine/viewer/bookmarks.h"
#include "engine/viewer/input_script.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace globe {
namespace {

InputEvent key(int code) { return {InputEvent::Type::kKey, code, true, 0, 0}; }
InputEvent character(char c) { return {InputEvent::Type::kChar, c, true, 0, 0}; }

struct TempDir {
  std::filesystem::path path = std::filesystem::temp_directory_path() / ("globe_places_" + std::to_string(::getpid()));
  TempDir() { std::filesystem::remove_all(path); }
  ~TempDir() { std::filesystem::remove_all(path); }
};

TEST(Bookmarks, RoundTripWithShortestNumbers) {
  std::vector<Bookmark> list = {{GeodeticPose{22.12, -0.0, 1500, 90, -10, 0}, "the Alps at dusk"},
                                {GeodeticPose{-33.9, 151.2, 2, 0, 0, 0}, ""}};
  const std::string text = formatBookmarks(list);
  EXPECT_NE(text.find("22.12,0,1500,90,-10,0 the Alps at dusk\n"), std::string::npos) << text;
  auto back = parseBookmarks(text, "b.txt");
  ASSERT_TRUE(back) << back.error().format();
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ((*back)[0].name, "the Alps at dusk");
  EXPECT_DOUBLE_EQ((*back)[1].pose.longitude_deg, 151.2);
}

TEST(Bookmarks, ErrorsNameFileLineAndField) {
  auto bad = parseBookmarks("# mine\n1,2,3,4,5,6 ok\n1,2,3 short\n", "b.txt");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().format(), "b.txt:3: place: expected LAT,LON,HEIGHT,HEADING,PITCH,ROLL, got '1,2,3'");
  auto range = parseBookmarks("91,2,3,4,5,6\n", "b.txt");
  ASSERT_FALSE(range);
  EXPECT_EQ(range.error().file, "b.txt");
  EXPECT_EQ(range.error().line, 1);
  EXPECT_NE(range.error().format().find("latitude"), std::string::npos) << range.error().format();
}

TEST(Bookmarks, MissingFileIsEmptyAndSavingMakesTheDirectory) {
  TempDir dir;
  const std::string file = (dir.path / "sub" / "bookmarks.txt").string();
  auto none = loadBookmarks(file);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
  ASSERT_TRUE(saveBookmarks(file, {{GeodeticPose{1, 2, 3, 4, 5, 6}, "x"}}));
  auto back = loadBookmarks(file);
  ASSERT_TRUE(back);
  ASSERT_EQ(back->size(), 1u);
  EXPECT_EQ((*back)[0].name, "x");
}

TEST(Bookmarks, GoToTakesWhatIsLeftOutFromTheCurrentPose) {
  const GeodeticPose current{10, 20, 750, 45, -5, 0};
  auto two = parseGoTo(" 46.5,7.9 ", current);
  ASSERT_TRUE(two) << two.error().format();
  EXPECT_DOUBLE_EQ(two->height_m, 750);
  EXPECT_DOUBLE_EQ(two->heading_deg, 45);
  auto three = parseGoTo("46.5,7.9,2000", current);
  ASSERT_TRUE(three);
  EXPECT_DOUBLE_EQ(three->height_m, 2000);
  EXPECT_DOUBLE_EQ(three->pitch_deg, -5);
  auto six = parseGoTo("46.5,7.9,2000,180,-20,0", current);
  ASSERT_TRUE(six);
  EXPECT_DOUBLE_EQ(six->heading_deg, 180);
  for (const char* bad : {"", "46.5", "1,2,3,4", "1,2,3,4,5", "1,2,3,4,5,6,7", "95,0", "1,2,-5", "a,b"}) {
    auto r = parseGoTo(bad, current);
    ASSERT_FALSE(r) << bad;
    EXPECT_EQ(r.error().format().rfind("go to: ", 0), 0u) << r.error().format();
  }
}

TEST(ViewerPlaces, TypedDigitsGoToTheLineNotToBookmarks) {
  ViewerPlaces places("unused.txt", {{GeodeticPose{1, 2, 3, 0, 0, 0}, "one"}});
  EXPECT_TRUE(places.handle(key(GLFW_KEY_G)));
  EXPECT_TRUE(places.typing());
  EXPECT_TRUE(places.handle(key(GLFW_KEY_4)));  // a digit key is the line's, not bookmark 4
  EXPECT_FALSE(places.pending());
  for (char c : std::string("g46.5,7x.9,12000")) EXPECT_TRUE(places.handle(character(c)));  // letters dropped
  EXPECT_EQ(places.typed(), "46.5,7.9,12000");
  EXPECT_TRUE(places.handle(key(GLFW_KEY_BACKSPACE)));
  EXPECT_TRUE(places.handle(key(GLFW_KEY_ESCAPE)));  // cancels; the viewer does not see it (no quit)
  EXPECT_FALSE(places.typing());
  EXPECT_FALSE(places.pending());

  places.handle(key(GLFW_KEY_G));
  for (char c : std::string("46.5,7.9,12000")) places.handle(character(c));
  places.handle(key(GLFW_KEY_ENTER));
  std::string message;
  auto pose = places.apply(GeodeticPose{0, 0, 100, 0, 0, 0}, message);
  ASSERT_TRUE(pose) << message;
  EXPECT_DOUBLE_EQ(pose->latitude_deg, 46.5);
  EXPECT_DOUBLE_EQ(pose->height_m, 12000);
  EXPECT_NE(message.find("went to 46.50000, 7.90000"), std::string::npos) << message;

  EXPECT_FALSE(places.handle({InputEvent::Type::kKey, GLFW_KEY_W, false, 0, 0}));  // releases pass
  EXPECT_FALSE(places.handle(key(GLFW_KEY_W)));
}

TEST(ViewerPlaces, MarkSavesAndNumbersGoBack) {
  TempDir dir;
  const std::string file = (dir.path / "b.txt").string();
  ViewerPlaces places(file, {});
  std::string message;
  places.handle(key(GLFW_KEY_3));
  EXPECT_FALSE(places.apply(GeodeticPose{}, message));
  EXPECT_NE(message.find("no bookmark 3"), std::string::npos) << message;
  places.handle(key(GLFW_KEY_M));
  const GeodeticPose here{46.5, 7.9, 2, 120, -3, 0};
  EXPECT_FALSE(places.apply(here, message));
  EXPECT_NE(message.find("saved bookmark 1"), std::string::npos) << message;
  auto saved = loadBookmarks(file);
  ASSERT_TRUE(saved);
  ASSERT_EQ(saved->size(), 1u);
  places.handle(key(GLFW_KEY_1));
  auto pose = places.apply(GeodeticPose{}, message);
  ASSERT_TRUE(pose);
  EXPECT_DOUBLE_EQ(pose->heading_deg, 120);
}

TEST(ViewerPlaces, ABookmarkThatCannotBeSavedSaysSo) {
  ViewerPlaces places("/proc/no/such/dir/b.txt", {});
  places.handle(key(GLFW_KEY_M));
  std::string message;
  places.apply(GeodeticPose{1, 2, 3, 0, 0, 0}, message);
  EXPECT_EQ(message.rfind("bookmark not saved: ", 0), 0u) << message;
  EXPECT_TRUE(places.bookmarks().empty());
}

TEST(InputScript, TextTypesOneCharacterEach) {
  auto s = parseInputScript("5 KEY G down\n6 TEXT 46.5,7.9\n7 KEY ENTER down\n8 KEY BACKSPACE down\n", "s.txt");
  ASSERT_TRUE(s) << s.error().format();
  auto frame6 = s->take(6);
  ASSERT_EQ(frame6.size(), 1u + 8u);
  EXPECT_EQ(frame6[1].type, InputEvent::Type::kChar);
  EXPECT_EQ(frame6[1].code, '4');
  EXPECT_EQ(frame6.back().code, '9');
  auto bad = parseInputScript("1 TEXT\n", "s.txt");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().format(), "s.txt:1: expected 'FRAME TEXT CHARACTERS' (no spaces)");
}

}  // namespace
}  // namespace globe
