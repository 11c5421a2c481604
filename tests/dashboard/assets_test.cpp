#include "dashboard/assets.h"

#include <gtest/gtest.h>

#include <string>

namespace {

TEST(DashboardAssets, RootIsTheIndexPage) {
  const dashboard::Asset* root = dashboard::find_asset("/");
  ASSERT_NE(root, nullptr);
  EXPECT_EQ(root->path, "/index.html");
  EXPECT_EQ(root->content_type, "text/html; charset=utf-8");
  EXPECT_NE(root->body.find("<!doctype html>"), std::string_view::npos);
  EXPECT_EQ(dashboard::find_asset("/index.html"), root);
}

TEST(DashboardAssets, ThePageReferencesAssetsThatExist) {
  // The page names its files relative to itself ("assets/app.js"): a classroom seat serves it
  // under /seats/K/ (docs/classroom.md).
  const std::string_view html = dashboard::find_asset("/")->body;
  for (const char* path : {"/assets/app.js", "/assets/app.css"}) {
    EXPECT_NE(html.find(std::string("\"") + (path + 1) + "\""), std::string_view::npos) << path;
    const dashboard::Asset* a = dashboard::find_asset(path);
    ASSERT_NE(a, nullptr) << path;
    EXPECT_GT(a->body.size(), 100u) << path;
  }
  EXPECT_EQ(dashboard::find_asset("/assets/app.js")->content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(dashboard::find_asset("/assets/app.css")->content_type, "text/css; charset=utf-8");
}

TEST(DashboardAssets, TheClassroomOverviewReferencesAssetsThatExist) {
  const dashboard::Asset* page = dashboard::find_asset("/classroom/index.html");
  ASSERT_NE(page, nullptr);
  for (const char* path : {"/classroom/classroom.js", "/classroom/classroom.css"}) {
    EXPECT_NE(page->body.find(std::string("\"") + (path + 1) + "\""), std::string_view::npos) << path;
    const dashboard::Asset* a = dashboard::find_asset(path);
    ASSERT_NE(a, nullptr) << path;
    EXPECT_GT(a->body.size(), 100u) << path;
  }
}

TEST(DashboardAssets, TheBodyIsTheWholeFileWithoutATerminator) {
  const std::string_view html = dashboard::find_asset("/")->body;
  EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
}

TEST(DashboardAssets, UnknownPathsAreNotFound) {
  EXPECT_EQ(dashboard::find_asset(""), nullptr);
  EXPECT_EQ(dashboard::find_asset("/nope.js"), nullptr);
  EXPECT_EQ(dashboard::find_asset("/assets/"), nullptr);
  EXPECT_EQ(dashboard::find_asset("index.html"), nullptr);
  EXPECT_EQ(dashboard::find_asset("/assets/app.js/"), nullptr);
}

}  // namespace
