#!/usr/bin/python3
"""The interactive Campbell report (src/writers/campbell_html.hpp) in headless Chromium.

whirl campbell --html on the NREL 5MW (cases/nrel5mw/Main_Onshore.fst), then the page in Debian's
chromium through chromium-driver and python3-selenium, without a network: no console error, one line
per Campbell line and one point per (line, point) row of campbell.csv in each panel, no resource
fetched over a network, a click on a point starts the animation (the canvas changes from frame to
frame); the screenshot stays in the output folder (build/tests/campbell_report/).

Usage: campbell_report.py WHIRL SOURCE_DIR OUT_DIR. Exit 77 (skipped) without chromium or selenium.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

SKIP = 77


def main():
    whirl, source, out = sys.argv[1], sys.argv[2], sys.argv[3]
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        from selenium.webdriver.common.by import By
    except ImportError:
        print("skipped: python3-selenium is not installed")
        return SKIP
    driver_path = shutil.which("chromedriver") or "/usr/bin/chromedriver"
    if not os.path.exists(driver_path) or not os.path.exists("/usr/bin/chromium"):
        print("skipped: chromium or chromium-driver is not installed")
        return SKIP
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    case = os.path.join(source, "cases", "nrel5mw", "Main_Onshore.fst")
    subprocess.run([whirl, "campbell", case, "--rpm", "0:4:12", "--azimuths", "12", "--no-plot", "--html",
                    "--out", out], check=True, stdout=subprocess.DEVNULL)
    page = os.path.join(out, "campbell.html")
    with open(os.path.join(out, "campbell.csv")) as f:
        rows = list(csv.DictReader(f))
    lines = len({r["mode"] for r in rows})

    profile = tempfile.mkdtemp(prefix="whirl-chromium-")
    opts = webdriver.ChromeOptions()
    opts.binary_location = "/usr/bin/chromium"
    for flag in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run", "--user-data-dir=" + profile,
                 "--window-size=1400,1000"]:
        opts.add_argument(flag)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(driver_path), options=opts)
    failures = []
    try:
        driver.get("file://" + os.path.abspath(page))
        time.sleep(1.0)
        for panel in ["freq", "damp"]:
            n_lines = len(driver.find_elements(By.CSS_SELECTOR, "#%s path.line" % panel))
            n_points = len(driver.find_elements(By.CSS_SELECTOR, "#%s circle.pt" % panel))
            if n_lines != lines:
                failures.append("%s panel: %d lines, campbell.csv has %d" % (panel, n_lines, lines))
            if n_points != len(rows):
                failures.append("%s panel: %d points, campbell.csv has %d rows" % (panel, n_points, len(rows)))
        legend = len(driver.find_elements(By.CSS_SELECTOR, "#legend .entry"))
        if legend != lines:
            failures.append("legend: %d entries for %d lines" % (legend, lines))
        resources = driver.execute_script(
            "return performance.getEntriesByType('resource').map(function (e) { return e.name; });")
        remote = [r for r in resources if not r.startswith(("file:", "data:", "blob:"))]
        if remote:
            failures.append("fetched over a network: %s" % remote)
        # A point of the highest-frequency line of the last rotor speed, clicked: the animation runs.
        target = driver.find_elements(By.CSS_SELECTOR, "#freq circle.pt")[-1]
        driver.execute_script("arguments[0].dispatchEvent(new MouseEvent('click', {bubbles: true}));", target)
        time.sleep(0.3)
        first = driver.execute_script("return document.getElementById('view').toDataURL();")
        frames0 = driver.execute_script("return window.whirlAnimation.frames;")
        time.sleep(0.5)
        second = driver.execute_script("return document.getElementById('view').toDataURL();")
        frames1 = driver.execute_script("return window.whirlAnimation.frames;")
        if first == second:
            failures.append("the canvas did not change after a click on a point")
        if not frames1 > frames0:
            failures.append("no animation frame drawn (%s -> %s)" % (frames0, frames1))
        selected = driver.execute_script("return window.whirlAnimation.selected;")
        # Hover shows the tooltip with the mode's name.
        driver.execute_script("arguments[0].dispatchEvent(new MouseEvent('mouseover', {bubbles: true}));", target)
        tip = driver.find_element(By.ID, "tooltip").text
        if "frequency" not in tip or "dominant" not in tip:
            failures.append("tooltip without frequency and dominant coordinates: %r" % tip)
        # The legend hides a line in both panels.
        driver.find_elements(By.CSS_SELECTOR, "#legend .entry")[0].click()
        hidden = len(driver.find_elements(By.CSS_SELECTOR, "#freq path.line.hidden, #damp path.line.hidden"))
        if hidden != 2:
            failures.append("legend click hid %d paths, expected 2" % hidden)
        driver.save_screenshot(os.path.join(out, "campbell_report.png"))
        errors = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
        if errors:
            failures.append("console errors: %s" % errors)
        print("%d lines, %d points, selected %s, %d -> %d frames, screenshot %s" %
              (lines, len(rows), selected, frames0, frames1, os.path.join(out, "campbell_report.png")))
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
