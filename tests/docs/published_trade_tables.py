#!/usr/bin/python3
"""The published trade tables are what their committed records give (docs/study.md,
"Campaign records"; docs/results/certificate): trade_table.py run again on each records
folder that holds a trade.json writes the same trade.json, number for number.

Usage: published_trade_tables.py SOURCE_DIR
"""
import json
import os
import sys
import tempfile


def main(source):
    sys.path.insert(0, os.path.join(source, "cases", "tradeoff"))
    import trade_table

    root = os.path.join(source, "docs", "results", "certificate")
    checked, failed = 0, []
    for study in sorted(os.listdir(root)):
        records = os.path.join(root, study)
        published = os.path.join(records, "trade.json")
        if not os.path.isfile(published):
            continue
        with tempfile.TemporaryDirectory() as out, open(os.devnull, "w") as quiet:
            stdout, sys.stdout = sys.stdout, quiet
            try:
                trade_table.main(records, out, figures=False)
            finally:
                sys.stdout = stdout
            again = json.load(open(os.path.join(out, "trade.json")))
        if again != json.load(open(published)):
            failed.append(study)
        checked += 1
    print(f"{checked} published table(s) checked against their records")
    if failed:
        sys.exit("not what their records give (run docs/results/certificate/make_tables.sh): "
                 + ", ".join(failed))
    if checked == 0:
        sys.exit("no published trade.json under docs/results/certificate")


if __name__ == "__main__":
    main(sys.argv[1])
