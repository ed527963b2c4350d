#!/usr/bin/env python3
"""Writes the weather-file variants of this folder (README.md lists what each exercises).

Every file is synthetic: a short data period (a day or three) of made-up but plausible
hourly values, in the layout of the EnergyPlus "EPW Data Dictionary" (Auxiliary Programs)
or of a RADIANCE/DAYSIM .wea file. Run from anywhere: python3 make_corpus.py
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

LOCATION = "LOCATION,Testville,CA,USA,SYNTH,999999,37.72,-122.22,-8.0,2.0"
HOLIDAYS = "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0"
DAYS_IN_MONTH = [31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]


def fields(year, month, day, hour):
    """The 35 fields of one record; DNI and DHI depend on the hour so that rows differ."""
    sun = 8 <= hour <= 17
    dni = 100 + 10 * hour if sun else 0
    dhi = 50 + hour if sun else 0
    return [str(year), str(month), str(day), str(hour), "0",
            "?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9*9*9",
            "9.0", "7.0", "87", "102000",
            str(800 if sun else 0), str(1300 if sun else 0), "305", str(400 if sun else 0),
            str(dni), str(dhi),
            str(45000 if sun else 0), str(30000 if sun else 0), str(9000 if sun else 0),
            str(3000 if sun else 0),
            "130", "2.6", "4", "4", "24.1", "77777", "9", "999999999", "129", "0.1120", "0",
            "88", "0.160", "999.0", "99.0"]


def days(start, end):
    """(month, day) from start to end inclusive, Feb 29 included."""
    m, d = start
    out = [(m, d)]
    while (m, d) != end:
        d += 1
        if d > DAYS_IN_MONTH[m - 1]:
            m, d = m + 1, 1
        out.append((m, d))
    return out


def epw(name, start=(1, 1), end=(1, 2), year=2015, location=LOCATION, holidays=HOLIDAYS,
        period=None, edit=None, bom=False):
    """An EPW file of the hours of start..end; `edit(records)` changes fields in place
    (records[i] is the field list of the i-th record, 0-based)."""
    if period is None:
        period = "DATA PERIODS,1,1,Data,Thursday, %d/%d,%d/%d" % (start + end)
    records = [fields(year, m, d, h) for (m, d) in days(start, end) for h in range(1, 25)]
    if edit:
        edit(records)
    lines = [location, "DESIGN CONDITIONS,0", "TYPICAL/EXTREME PERIODS,0",
             "GROUND TEMPERATURES,0", holidays, "COMMENTS 1,synthetic variant for dayphoton's tests",
             "COMMENTS 2,values are made up", period]
    lines += [",".join(r) for r in records]
    with open(os.path.join(HERE, name), "w", newline="", encoding="utf-8-sig" if bom else "utf-8") as f:
        f.write("".join(line + "\r\n" for line in lines))


def setf(records, index, field, value):
    records[index][field - 1] = value


def unused_junk(records):
    # Present weather observation (field 27) outside 0..9 or not a number, as in files where
    # the field is filled by other conventions, plus a humidity and a wind direction that are
    # out of range and a letter in the visibility: 14 problems, none in a field the sky uses.
    for i in range(10):
        setf(records, i, 27, "12" if i % 2 else "x")
    setf(records, 12, 9, "150")
    setf(records, 13, 21, "400")
    setf(records, 14, 25, "9k")
    setf(records, 15, 33, "-1")


def short_gaps(records):
    # Jan 1 hours 10 and 11 (two consecutive records) lack DNI (9999, the EPW missing code);
    # Jan 2 hour 12 has an empty DHI field. Both gaps are at most two hours: interpolated.
    setf(records, 9, 15, "9999")
    setf(records, 10, 15, "9999")
    setf(records, 24 + 11, 16, "")


def long_gap(records):
    # Jan 1 hours 10, 11 and 12 lack DNI: three hours, more than may be interpolated.
    for i in (9, 10, 11):
        setf(records, i, 15, "9999")


def gap_at_start(records):
    # The first record (Jan 1 hour 1) lacks DHI: one neighbour only, its value is held.
    setf(records, 0, 16, "9999")


def broken_used_fields(records):
    # Broken values in fields the sky uses: located errors.
    setf(records, 11, 16, "abc")      # Jan 1 hour 12: DHI not a number
    setf(records, 12, 15, "-3")       # Jan 1 hour 13: DNI negative
    setf(records, 13, 8, "dew")       # Jan 1 hour 14: dew point not a number


def ladybug_style(records):
    for i in range(0, 48, 3):
        setf(records, i, 27, "")


def wea(name, header, rows, bom=False):
    with open(os.path.join(HERE, name), "w", newline="", encoding="utf-8-sig" if bom else "utf-8") as f:
        f.write("".join(line + "\n" for line in header + rows))


WEA_HEADER = ["place Testville_USA", "latitude 37.72", "longitude 122.22", "time_zone 120",
              "site_elevation 2.0", "weather_data_file_units 1"]


def wea_rows(start=(1, 1), end=(1, 2)):
    rows = []
    for (m, d) in days(start, end):
        for h in range(1, 25):
            f = fields(2015, m, d, h)
            rows.append("%d %d %.3f %s %s" % (m, d, h - 0.5, f[14], f[15]))
    return rows


def main():
    epw("clean.epw")
    epw("dates_year_first.epw", period="DATA PERIODS,1,1,Data,Thursday,2015/1/1,2015/1/2")
    epw("dates_with_year.epw", period="DATA PERIODS,1,1,Data,Thursday,1/1/2015,1/2/2015")
    epw("location_11_fields.epw",
        location="LOCATION,Testville,CA,USA,SYNTH,999999,37.72,-122.22,-8.0,2.0,0")
    epw("leap_flag_empty.epw", holidays="HOLIDAYS/DAYLIGHT SAVINGS,,0,0,0")
    epw("leap_day_declared.epw", start=(2, 28), end=(3, 1), year=2016,
        holidays="HOLIDAYS/DAYLIGHT SAVINGS,Yes,0,0,0")
    epw("leap_day_undeclared.epw", start=(2, 28), end=(3, 1), year=2016)
    epw("leap_day_flag_empty.epw", start=(2, 28), end=(3, 1), year=2016,
        holidays="HOLIDAYS/DAYLIGHT SAVINGS,,0,0,0")
    epw("unused_fields_junk.epw", edit=unused_junk)
    epw("missing_short_gaps.epw", edit=short_gaps)
    epw("missing_long_gap.epw", edit=long_gap)
    epw("missing_at_start.epw", edit=gap_at_start)
    epw("used_fields_broken.epw", edit=broken_used_fields)
    epw("ladybug_style.epw",
        location="LOCATION,Testville,CA,USA,SYNTH,999999,37.72,-122.22,-8.0,2.0,0",
        holidays="HOLIDAYS/DAYLIGHT SAVINGS,,0,0,0",
        period="DATA PERIODS,1,1,Data,Thursday,2015/1/1,2015/1/2", edit=ladybug_style)
    epw("utf8_bom.epw", bom=True)
    wea("hourly.wea", WEA_HEADER, wea_rows())
    wea("utf8_bom.wea", WEA_HEADER, wea_rows(), bom=True)
    wea("hourly_leap_day.wea", WEA_HEADER, wea_rows((2, 28), (3, 1)))
    bad = wea_rows()
    bad[30] = "1 2 6.500 12x 3"
    wea("bad_value.wea", WEA_HEADER, bad)
    gap = wea_rows()
    del gap[20]
    wea("missing_hour.wea", WEA_HEADER, gap)
    integer_hours = [r.replace(".500 ", ".000 ", 1) for r in wea_rows()]
    wea("integer_hours.wea", WEA_HEADER, integer_hours)
    wea("units_illuminance.wea", WEA_HEADER[:5] + ["weather_data_file_units 3"], wea_rows())


if __name__ == "__main__":
    main()
