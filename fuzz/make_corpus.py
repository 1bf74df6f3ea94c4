#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (fuzz/corpus/<target>/) from the project's real
examples: the Jake mission and hazard file, the message examples of include/*/messages, and
MOOS packets encoded as docs/protocol.md describes (section 2.1). Run from anywhere; the corpora
are committed, this script only says where each seed came from and rebuilds them."""

import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
JAKE = ROOT / "missions" / "jake"


def write(target, name, data):
    folder = HERE / "corpus" / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def hazard_lines():
    return [l.split("=", 1)[1].strip() for l in (JAKE / "hazards.txt").read_text().splitlines()
            if l.startswith("hazard")]


def seed_hazard_parsers():
    for i, line in enumerate(hazard_lines()[:4]):
        write("hazard_line", f"jake{i}", line)
    write("hazard_line", "aspect", "x=37,y=-207,label=99,type=benign,hr=0.73,aspect=57,"
          "aspect_min=20,aspect_max=45")
    write("hazard_line", "latlon", "lat=43.8253,lon=-70.3304,label=7,type=hazard,color=red,"
          "shape=circle,width=4")
    write("hazard_file", "jake", (JAKE / "hazards.txt").read_text())
    write("hazard_file", "latlon", "// geodesy\nsource = gen_hazards\n"
          "hazard = lat=43.8253,lon=-70.3304,label=a,type=hazard\n"
          "hazard = x=1,y=2,label=b,hazard=false\nbogus line\n")
    # A known crash: the field wider than the largest double (aborted uFldHazardSensor at start-up).
    write("hazard_file", "far_apart", "hazard = x=9e307,y=0,label=a,type=hazard\n"
          "hazard = x=-9e307,y=0,label=b,type=benign\n")
    write("node_report", "example", "NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,"
          "TIME=123,TYPE=kayak")
    write("node_report", "latlon", "NAME=betty,LAT=43.82,LON=-70.33,SPEED=2,HEADING=1e15,"
          "MODE={A,B}")
    write("config_request", "width", "vname=archie,width=50,pd=0.9")
    write("config_request", "pd", "vname=archie,pd=0.75")
    write("sensor_request", "example", "vname=archie")
    write("sensor_clear", "example", "vname=archie")
    write("classify_request", "plain", "vname=archie,label=152")
    write("classify_request", "top", "vname=archie,label=152,priority=100,action=top")
    outputs = [
        "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8",
        "vname=archie,x=-52,y=-290,label=75",
        "vname=archie,x=-52,y=-290,label=75,type=hazard",
        "width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60:width=10,exp=6,pclass=0.93,max=1",
        "x=-52,y=-290,radius=10,vertices=12,duration=60,edge_color=white,fill_color=white,"
        "time=12.5,vertex_size=0,edge_size=1,fill_transparency=0.3",
        "x=-52,y=-290,width=8,primary_color=green,type=triangle,label=75",
        "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie,msg=0.90,"
        "edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2",
        "pts={37,-192:37,-222},edge_color=gray70,vertex_size=0,edge_size=1",
    ]
    for i, text in enumerate(outputs):  # the first byte picks the parser (sensor_outputs.cpp)
        write("sensor_outputs", f"parser{i}", bytes([i]) + text.encode())


def seed_mission_mail():
    texts = [
        "source=archie#dest=betty#prior=0.5#label=75,x=-52,y=-290,evidence=2.841,det=1,miss=0,"
        "said_hazard=1,said_benign=0#label=82,x=-41,y=-246,evidence=-1.5347,det=1,miss=0,"
        "said_hazard=0,said_benign=1",
        "true",
        "86.666667",
        "vname=archie,report_name=archie,total_score=20,norm_score=86.67,score_missed_hazards=0,"
        "score_false_alarms=20,score_time_overage=0,total_objects=7,total_time=0,"
        "received_time=812.5",
        "source=archie#name=archie#x=-52,y=-290,label=75#x=41,y=-108,label=53",
        "penalty_missed_hazard=100,penalty_nonopt_hazard=50,penalty_false_alarm=10,"
        "penalty_max_time_over=0,max_time=0,penalty_max_time_rate=0,transit_path_width=20,"
        "search_region=pts={-150,-75:-150,-400:400,-400:400,-75}",
    ]
    for i, text in enumerate(texts):  # the first byte picks the parser (mission_mail.cpp)
        write("mission_mail", f"parser{i}", bytes([i]) + text.encode())


def seed_text_files():
    write("moos_mission", "jake", (JAKE / "jake.moos").read_text())
    write("moos_mission", "habits", "ServerHost = localhost\nMOOSTimeWarp = $(WARP)\n"
          "define: HOST = ${ServerHost}\n#include \"plugs.def\"\n#ifdef X\n"
          "ProcessConfig = pA\n{\n  name = $(VNAME) // $(MISSING)\n  v = \"a//b\"\n}\n"
          "ProcessConfig = pB {\n}\n")
    start = "%% LOG FILE: input.alog\n%% LOGSTART 1700000000.0\n%%%%%%%%%%%%%%%%\n"
    alog = (start +
            "0.000 NODE_REPORT test NAME=archie,X=-60,Y=-280,SPD=2,HDG=90,TIME=0\n"
            "0.500 UHZ_SENSOR_REQUEST test vname=archie\n"
            "1.000 UHZ_CONFIG_REQUEST test vname=archie,width=25,pd=0.9\n"
            "2.000 UHZ_CLASSIFY_REQUEST test vname=archie,label=75,priority=90\n"
            "3.250 UHZ_SENSOR_CLEAR test vname=archie\n"
            "4.000 NODE_REPORT test NAME=archie,LAT=43.823,LON=-70.331,SPD=2,HDG=45\n")
    write("alog", "replay_input", alog)
    write("replay", "requests", alog)
    write("command_line", "sensor", "jake.moos\0uFldHazardSensor_2\0--moos_port=9001\0--SEED=3")
    write("command_line", "server", "--moos_port=9000\0--moos_community=shoreside\0-h")
    write("command_line", "replay", "--seed=1\0--until=60\0--output=out.alog\0c.moos\0in.alog")
    write("study_args", "settings", "jake.moos\0--seeds=1..3\0--setting=W10\0"
          "--set=pHazardMgr_archie.swath_width=10\0--set=uFldHazardSensor.max_turn_rate=off\0"
          "--max-time=900\0--alog=one.alog\0--WARP=1")
    write("study_args", "field", "jake.moos\0--field=--polygon=-150,-75:-150,-400:400,-400:400,-75 "
          "--objects=8,hazard --objects=6,benign\0--field-seeds=1..2\0--seeds=4")


def message(mtype, dtype, key, sval=b"", dval=-1.0, source=b"fuzz", ident=0, time=1.7e9):
    def string(s):
        return struct.pack("<i", len(s)) + s
    body = (struct.pack("<i", ident) + mtype + dtype + string(source) + string(b"") +
            string(b"#1") + string(key) + struct.pack("<ddd", time, dval, -1.0) + string(sval))
    return struct.pack("<i", 4 + len(body)) + body


def packet(*messages):
    payload = b"".join(messages)
    return struct.pack("<ii", 9 + len(payload), len(messages)) + b"\0" + payload


def seed_numbers():
    # Texts for parse_number (the exact short path, long mantissas, edges of double) whose
    # first nine bytes also make a double and a decimal count for fix and fmt.
    for name, text in [("coordinate", "-9997.75"), ("epoch", "1700000000.100"),
                       ("exponent", "2.5E-1"), ("tie", "0.125"), ("plus", "+.5"),
                       ("underflow", "1e-400"), ("overflow", "1.7976931348623159e308"),
                       ("long", "0." + "0" * 30 + "1e31"), ("junk", "1e+ nan")]:
        write("number", name, text)
    write("number", "double_tie", struct.pack("<d", 10000.25) + bytes([1]))
    write("number", "double_tiny", struct.pack("<d", -1e-10) + bytes([12]))


def seed_wire():
    ident = packet(message(b"i", b"S", b"asynchronous", b"pFuzz", ident=-1))
    mail = packet(
        message(b"N", b"D", b"NAV_X", dval=12.5),
        message(b"N", b"S", b"NODE_REPORT", b"NAME=archie,X=1,Y=2,SPD=1,HDG=0"),
        message(b"N", b"B", b"BLOB", b"\x00\x01\x02"),
        message(b"R", b"D", b"NAV_X", dval=0.5),
        message(b"*", b"S", b"pFuzz", b"AppPattern=*,VarPattern=NAV_*,Interval=0"),
        message(b"Q", b"S", b"ALL", ident=-2),
        message(b"U", b"D", b"NAV_X"),
        message(b".", b"D", b""))
    write("wire_server", "session", ident + mail)
    write("wire_server", "sync_client", packet(message(b"i", b"S", b"", b"pSync", ident=-1)) +
          packet(message(b"T", b"D", b"_async_timing")) + packet(message(b"/", b"S", b"pSync",
                                                                          b"AppPattern=*")))
    welcome = packet(message(b"W", b"S", b"hostname=dbhost", b"", source=b"MOOSDB_#1"))
    write("wire_client", "welcome", b"\x07" + welcome + mail)
    write("wire_client", "poison", b"\x01" + packet(message(b"K", b"S", b"", b"Failed")))


def seed_web_requests():
    """Requests as fuzz/web_request.cpp reads them: method, Host, Origin, Sec-Fetch-Site, token."""
    token = "0123456789abcdef0123456789abcdef"
    write("web_request", "page", "GET\n127.0.0.1:8080\n\n\n")
    write("web_request", "button", f"POST\n127.0.0.1:8080\nhttp://127.0.0.1:8080\nsame-origin\n{token}")
    write("web_request", "cross_site_form", "POST\n127.0.0.1:8080\nhttp://evil.test\ncross-site\n")
    write("web_request", "rebound", "GET\nevil.test:8080\n\n\n")
    write("web_request", "ipv6", "GET\n[::1]:8080\n\n\n")
    write("web_request", "binary_value", b"GET\nlocalhost:8080\n\xff\xc0\xafx\xe2\x82\n\x00")


if __name__ == "__main__":
    seed_hazard_parsers()
    seed_mission_mail()
    seed_text_files()
    seed_wire()
    seed_numbers()
    seed_web_requests()
