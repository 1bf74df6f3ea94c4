// The engine's MOOS interface as data (--interface, the docs, the driver's dispatch).
#include "hazard/engine.hpp"

namespace hazard {

const std::vector<InterfaceVariable>& Engine::subscriptions() {
  static const std::vector<InterfaceVariable> v = {
      {"NODE_REPORT", "NAME=archie,X=51,Y=11.3,SPD=1.5,HDG=90", "a vehicle's pose"},
      {"UHZ_SENSOR_REQUEST", "vname=archie", "keep the vehicle's sensor on for 600 s"},
      {"UHZ_CONFIG_REQUEST", "vname=archie,width=25,pd=0.9", "choose a sensor setting"},
      {"UHZ_CLASSIFY_REQUEST", "vname=archie,label=12,priority=80",
       "classify a detected object (action=top or action=clear optional)"},
      {"UHZ_SENSOR_CLEAR", "vname=archie", "empty the vehicle's pending classifications"},
      {"PMV_CONNECT", "pMarineViewer", "post the object markers again"},
  };
  return v;
}

const std::vector<InterfaceVariable>& Engine::publications() {
  static const std::vector<InterfaceVariable> v = {
      {"UHZ_DETECTION_REPORT", "vname=archie,x=51,y=11.3,label=12", "a detection"},
      {"UHZ_DETECTION_REPORT_<V>", "x=51,y=11.3,label=12", "a detection, for vehicle V"},
      {"UHZ_HAZARD_REPORT", "vname=archie,x=51,y=11.3,label=12,type=hazard",
       "a classification answer"},
      {"UHZ_HAZARD_REPORT_<V>", "x=51,y=11.3,label=12,type=hazard",
       "a classification answer, for vehicle V"},
      {"UHZ_CONFIG_ACK", "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8",
       "the settings in force after a configuration"},
      {"UHZ_CONFIG_ACK_<V>", "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8",
       "the same, for vehicle V"},
      {"UHZ_OPTIONS_SUMMARY", "width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60",
       "the configured sensor options"},
      {"VIEW_POLYGON",
       "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie,msg=0.90,"
       "edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2",
       "a vehicle's swath"},
      {"VIEW_CIRCLE",
       "x=51,y=11.3,radius=10,vertices=12,edge_color=white,fill_color=white,time=12.5,"
       "vertex_size=0,edge_size=1,fill_transparency=0.3",
       "detection and classification cues"},
      {"VIEW_MARKER", "x=51,y=11.3,width=8,primary_color=green,type=triangle,label=12",
       "an object of the field"},
      {"VIEW_SEGLIST", "pts={51,26.3:51,-3.7},edge_color=gray70,vertex_size=0,edge_size=1",
       "an object's aspect axis"},
  };
  return v;
}

}  // namespace hazard
