// Buttons (pMarineViewer's convention), the block's parameters, and the JSON of the events.
#include <gtest/gtest.h>

#include <cmath>

#include "buttons.hpp"
#include "view_mail.hpp"
#include "viewer_config.hpp"

namespace web_viewer {
namespace {

moos::ConfigLine line(const std::string& key, const std::string& value, int n = 7) {
  return moos::ConfigLine{key, value, "m.moos", n};
}

TEST(Buttons, LabelThenAssignmentsNumbersAsDoubles) {
  std::string error;
  const auto b = parse_button(1, "DEPLOY # DEPLOY_ALL=true # SPEED = 2.5 # NOTE=go home", &error);
  ASSERT_TRUE(b) << error;
  EXPECT_EQ(b->label, "DEPLOY");
  ASSERT_EQ(b->assignments.size(), 3u);
  EXPECT_EQ(b->assignments[0].var, "DEPLOY_ALL");
  EXPECT_FALSE(b->assignments[0].is_double);
  EXPECT_EQ(b->assignments[0].sval, "true");
  EXPECT_EQ(b->assignments[1].var, "SPEED");
  EXPECT_TRUE(b->assignments[1].is_double);
  EXPECT_EQ(b->assignments[1].dval, 2.5);
  EXPECT_EQ(b->assignments[2].sval, "go home");
}

TEST(Buttons, BadButtonsAreRefusedWithAReason) {
  std::string error;
  EXPECT_FALSE(parse_button(1, "DEPLOY", &error));
  EXPECT_NE(error.find("no VAR=value"), std::string::npos);
  EXPECT_FALSE(parse_button(1, "DEPLOY # DEPLOY_ALL", &error));
  EXPECT_NE(error.find("is not VAR=value"), std::string::npos);
  EXPECT_FALSE(parse_button(1, " # A=1", &error));
  EXPECT_FALSE(parse_button(1, "A=1 # B=2", &error));
  EXPECT_FALSE(parse_button(1, "GO # =1", &error));
}

TEST(Buttons, OneToFourByName) {
  EXPECT_EQ(button_index("button_one"), 1);
  EXPECT_EQ(button_index("BUTTON_FOUR"), 4);
  EXPECT_FALSE(button_index("button_five"));
  EXPECT_FALSE(button_index("button"));
}

TEST(ViewerConfig, DefaultsWithoutLines) {
  std::vector<std::string> warnings;
  const ViewerConfig c = read_viewer_config({}, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(c.http.bind_address, "127.0.0.1");
  EXPECT_EQ(c.http.port, 8080);
  EXPECT_TRUE(c.buttons.empty());
  EXPECT_EQ(c.watch, default_watch());
  EXPECT_EQ(c.limits.retention.trail_length, 200u);
}

TEST(ViewerConfig, ParametersAreRead) {
  std::vector<std::string> warnings;
  const ViewerConfig c = read_viewer_config(
      {line("HTTP_PORT", "0"), line("http_bind", "0.0.0.0"), line("trail_length", "50"),
       line("max_clients", "3"), line("button_two", "STOP # RETURN_ALL=true"),
       line("watch", "HAZARDSET_REPORT, UHZ_*"), line("appcast_request", "false")},
      &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(c.http.port, 0);
  EXPECT_EQ(c.http.bind_address, "0.0.0.0");
  EXPECT_EQ(c.limits.retention.trail_length, 50u);
  EXPECT_EQ(c.limits.max_clients, 3u);
  ASSERT_EQ(c.buttons.size(), 1u);
  EXPECT_EQ(c.buttons[0].index, 2);
  EXPECT_EQ(c.watch.size(), default_watch().size() + 2);
  EXPECT_EQ(c.watch.back(), "UHZ_*");
  EXPECT_FALSE(c.appcast_request);
}

TEST(ViewerConfig, WatchDefaultsFalseKeepsOnlyTheListedVariables) {
  std::vector<std::string> warnings;
  const ViewerConfig c = read_viewer_config(
      {line("watch", "NODE_REPORT, DEPLOY_ALL"), line("watch_defaults", "false")}, &warnings);
  EXPECT_EQ(c.watch, (std::vector<std::string>{"NODE_REPORT", "DEPLOY_ALL"}));
}

TEST(ViewerConfig, BadLinesAreWarningsNamingThePlace) {
  std::vector<std::string> warnings;
  const ViewerConfig c = read_viewer_config(
      {line("http_port", "70000", 3), line("trail_length", "0", 4), line("button_one", "GO", 5),
       line("colour", "red", 6), line("watch", "A B", 8)},
      &warnings);
  ASSERT_EQ(warnings.size(), 5u);
  EXPECT_EQ(warnings[0], "m.moos:3: http_port='70000' is not a whole number in [0, 65535]");
  EXPECT_NE(warnings[1].find("m.moos:4: trail_length"), std::string::npos);
  EXPECT_NE(warnings[2].find("m.moos:5: button_one"), std::string::npos);
  EXPECT_EQ(warnings[3], "m.moos:6: unknown parameter 'colour'");
  EXPECT_NE(warnings[4].find("is not a variable name"), std::string::npos);
  EXPECT_EQ(c.http.port, 8080);
  EXPECT_TRUE(c.buttons.empty());
}

TEST(ViewJson, StringsAreEscapedAndSafeInsideAScriptElement) {
  EXPECT_EQ(json_string("a\"b\\c\nd"), "\"a\\\"b\\\\c\\nd\"");
  EXPECT_EQ(json_string("</script>&"), "\"\\u003c/script\\u003e\\u0026\"");
  EXPECT_EQ(json_string(std::string("\x01", 1)), "\"\\u0001\"");
  EXPECT_EQ(json_number(std::nan("")), "null");
}

// Every byte of the event stream is valid UTF-8: EventSource and JSON readers need it.
TEST(ViewJson, InvalidUtf8BecomesEscapedTextAndValidUtf8IsKept_Hardening) {
  EXPECT_EQ(json_string("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\xA2"), "\"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\xA2\"");
  EXPECT_EQ(json_string("a\xFF" "b"), R"("a\\xFFb")");
  EXPECT_EQ(json_string("\xC3"), R"("\\xC3")");                   // cut short at the end
  EXPECT_EQ(json_string("\xC0\xAF"), R"("\\xC0\\xAF")");           // overlong '/'
  EXPECT_EQ(json_string("\xED\xA0\x80"), R"("\\xED\\xA0\\x80")");  // a surrogate
  EXPECT_EQ(json_string("\xF4\x90\x80\x80"), R"("\\xF4\\x90\\x80\\x80")");  // beyond U+10FFFF
  EXPECT_EQ(json_string("\xE2\x82x"), R"("\\xE2\\x82x")");
  Mail binary;
  binary.var = "VIEW_MARKER";
  binary.sval = std::string("x=1,label=\x00\x80\xFE", 13);
  EXPECT_NE(mail_json(binary).find(R"(label=\u0000\\x80\\xFE")"), std::string::npos) << mail_json(binary);
}

TEST(ViewerConfig, AllowedHostsAreReadAndCheckedAsNames) {
  std::vector<std::string> warnings;
  const ViewerConfig c = read_viewer_config(
      {line("allowed_hosts", "Shoreside.Local, viewer-1.lab.example"), line("allowed_hosts", "[fe80::1], 10.0.0.7"),
       line("allowed_hosts", "evil/path", 3), line("allowed_hosts", "a b", 4)},
      &warnings);
  EXPECT_EQ(c.http.allowed_hosts,
            (std::vector<std::string>{"shoreside.local", "viewer-1.lab.example", "[fe80::1]", "10.0.0.7"}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("allowed_hosts: 'evil/path' is not a host name"), std::string::npos) << warnings[0];
}

TEST(ViewerConfig, TheHelloAnnouncesButtonsAndThePagesBounds) {
  std::vector<std::string> warnings;
  const Hello h = configured_hello(read_viewer_config(
      {line("button_three", "GO # A=1"), line("trail_length", "20"), line("unlabelled_ring", "30")}, &warnings));
  ASSERT_EQ(h.buttons.size(), 1u);
  EXPECT_EQ(h.buttons[0].index, 3);
  EXPECT_EQ(h.buttons[0].label, "GO");
  EXPECT_EQ(h.trail_length, 20u);
  EXPECT_EQ(h.unlabelled_ring, 30u);
}

TEST(ViewJson, MailCarriesDoublesAsNumbersAndStringsAsStrings) {
  Mail m;
  m.var = "SPEED";
  m.src = "sim";
  m.time_s = 12.5;
  m.is_double = true;
  m.dval = 1.25;
  EXPECT_EQ(mail_json(m), R"({"type":"mail","var":"SPEED","val":1.25,"src":"sim","time":12.5})");
  m.is_double = false;
  m.sval = "x=1";
  EXPECT_EQ(mail_json(m), R"({"type":"mail","var":"SPEED","val":"x=1","src":"sim","time":12.5})");
}

TEST(ViewJson, HelloNamesModeButtonsAndDatum) {
  Hello h;
  h.community = "jake";
  h.time_s = 100;
  h.warp = 50;
  h.buttons = {{1, "DEPLOY"}};
  EXPECT_EQ(hello_json(h), R"({"type":"hello","app":"pWebViewer","community":"jake","time":100,)"
                           R"("warp":50,"mode":"live","buttons":[{"index":1,"label":"DEPLOY"}],)"
                           R"("trail_length":200,"unlabelled_ring":2000})");
  h.replay = true;
  h.buttons.clear();
  h.lat_origin_deg = 43.8253;
  h.lon_origin_deg = -70.3304;
  EXPECT_EQ(hello_json(h), R"({"type":"hello","app":"pWebViewer","community":"jake","time":100,)"
                           R"("warp":50,"mode":"replay","buttons":[],"trail_length":200,"unlabelled_ring":2000,)"
                           R"("lat_origin":43.8253,"lon_origin":-70.3304})");
  EXPECT_EQ(clock_json(7, 2), R"({"type":"clock","time":7,"warp":2})");
}

}  // namespace
}  // namespace web_viewer
