#!/usr/bin/python3
"""Write cu-c001.csv, the undrained shearing stage of a consolidated-undrained triaxial test on a
soft clay, from the laboratory's raw GDSLAB export published in highjoule/triaxphases (README.md
beside this script gives the source, commit and licence).

    extract.py TRIAX10m.xls.xlsx [--out cu-c001.csv]

The workbook is read with the standard library only (an .xlsx file is a zip of XML sheets). Sheet
"Rawdata" holds one row per reading with the GDS column names; stage 3 is the undrained shear. The
CSV keeps, per reading of stage 3:

    eps_a  axial strain since the start of shearing, percent ("Axial Strain" minus its value at the
           stage's first reading: the K0 consolidation before it strained the specimen by 2.05 %)
    q      "Deviator Stress", kPa
    u      excess pore pressure, kPa ("Pore Pressure" minus its value at the stage's first reading)
    p      "Eff, Cambridge p'", kPa (not fitted; for the figures)

Readings whose axial strain does not exceed the previous reading's (the rig's resolution at the
start of the stage) are left out: the calibration places readings by a strictly increasing eps_a.
"""
import argparse
import re
import xml.etree.ElementTree as ET
import zipfile

MAIN = "{http://schemas.openxmlformats.org/spreadsheetml/2006/main}"
COLUMNS = {"stage": "Stage Number", "eps_a": "Axial Strain", "q": "Deviator Stress",
           "u": "Pore Pressure", "p": "Eff, Cambridge p'"}
SHEAR_STAGE = 3


def column_index(reference):
    index = 0
    for letter in re.match(r"[A-Z]+", reference).group(0):
        index = index * 26 + ord(letter) - ord("A") + 1
    return index - 1


def rows(workbook, sheet):
    """Each row of `sheet` as {column index: text}, shared strings resolved."""
    strings = [''.join(t.text or '' for t in item.iter(MAIN + "t"))
               for item in ET.fromstring(workbook.read("xl/sharedStrings.xml")).findall(MAIN + "si")]
    for row in ET.fromstring(workbook.read(sheet)).iter(MAIN + "row"):
        cells = {}
        for cell in row.findall(MAIN + "c"):
            value = cell.find(MAIN + "v")
            if value is not None:
                cells[column_index(cell.get("r"))] = (strings[int(value.text)] if cell.get("t") == "s"
                                                      else value.text)
        yield cells


def shear_readings(path):
    with zipfile.ZipFile(path) as workbook:
        # Sheet 1 is "Rawdata" (xl/workbook.xml); its header row names the columns.
        table = list(rows(workbook, "xl/worksheets/sheet1.xml"))
    header = next(k for k, row in enumerate(table) if COLUMNS["stage"] in row.values())
    where = {name: next(i for i, title in table[header].items() if title == title_wanted)
             for name, title_wanted in COLUMNS.items()}
    readings = [{name: float(row[i]) for name, i in where.items()} for row in table[header + 1:]]
    return [r for r in readings if r["stage"] == SHEAR_STAGE]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workbook")
    parser.add_argument("--out", default="cu-c001.csv")
    args = parser.parse_args()
    shear = shear_readings(args.workbook)
    eps0, u0 = shear[0]["eps_a"], shear[0]["u"]
    kept, last = [], None
    for r in shear:
        eps = r["eps_a"] - eps0
        if last is None or eps > last:
            kept.append((eps, r["q"], r["u"] - u0, r["p"]))
            last = eps
    with open(args.out, "w") as out:
        out.write("# Undrained shear (stage 3) of the CU triaxial test C001, 10 m, of highjoule/triaxphases "
                  "sample_test/TRIAX10m.xls.xlsx (Apache-2.0; data/calibration/lab-c001/README.md), written by "
                  "extract.py. eps_a since the start of shearing; u excess over the pore pressure then "
                  f"({u0:g} kPa). Compression-positive; stresses kPa; strains percent\n")
        out.write("eps_a,q,u,p\n")
        for eps, q, u, p in kept:
            out.write(f"{eps:.4f},{q:.4f},{u:.3f},{p:.4f}\n")
    print(f"{args.out}: {len(kept)} of {len(shear)} readings of stage {SHEAR_STAGE}")


if __name__ == "__main__":
    main()
