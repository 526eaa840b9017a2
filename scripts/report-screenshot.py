#!/usr/bin/python3
"""A screenshot of whirl's interactive Campbell report (campbell.html) for the README and the docs.

Usage: report-screenshot.py RESULT_DIR OUT.png [LINE [POINT]]

Opens RESULT_DIR/campbell.html in headless Chromium (Debian chromium, chromium-driver, python3-selenium;
no network), clicks the point POINT (0-based, default the middle one) of the Campbell line named LINE
(default "flap 1 BW") so the mode shape plays, waits a moment, and saves the window as a 256-colour PNG
(Pillow) to keep it small. `bash scripts/main.sh` writes reports/nrel5mw_aero/campbell.html; the README's
picture is `scripts/report-screenshot.py reports/nrel5mw_aero docs/campbell_report_nrel5mw_aero.png`.
"""
import json
import os
import shutil
import sys
import tempfile
import time


def main():
    if len(sys.argv) < 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    result, png = sys.argv[1], sys.argv[2]
    line_name = sys.argv[3] if len(sys.argv) > 3 else "flap 1 BW"
    from PIL import Image
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By

    with open(os.path.join(result, "campbell_modes.json")) as f:
        modes = json.load(f)
    if line_name not in modes["lines"]:
        print("no line %r in %s (lines: %s)" % (line_name, result, ", ".join(modes["lines"])), file=sys.stderr)
        return 1
    line = modes["lines"].index(line_name)
    point = int(sys.argv[4]) if len(sys.argv) > 4 else len(modes["points"]) // 2

    profile = tempfile.mkdtemp(prefix="whirl-chromium-")
    opts = webdriver.ChromeOptions()
    opts.binary_location = "/usr/bin/chromium"
    for flag in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
                 "--user-data-dir=" + profile, "--window-size=1400,900"]:
        opts.add_argument(flag)
    driver_path = shutil.which("chromedriver") or "/usr/bin/chromedriver"
    driver = webdriver.Chrome(service=Service(driver_path), options=opts)
    try:
        driver.get("file://" + os.path.abspath(os.path.join(result, "campbell.html")))
        time.sleep(1.0)
        target = driver.find_elements(By.CSS_SELECTOR, "#freq circle.pt.l%d.p%d" % (line, point))
        if not target:
            print("line %r has no point %d" % (line_name, point), file=sys.stderr)
            return 1
        driver.execute_script("arguments[0].dispatchEvent(new MouseEvent('click', {bubbles: true}));", target[0])
        time.sleep(0.8)
        raw = png + ".raw.png"
        driver.save_screenshot(raw)
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    Image.open(raw).convert("RGB").quantize(colors=256).save(png, optimize=True)
    os.remove(raw)
    print("%s: %s at point %d, %d bytes" % (png, line_name, point, os.path.getsize(png)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
