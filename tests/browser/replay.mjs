// replay.mjs - the replay page in a real browser: headless Chromium (Debian's
// chromium package) driven by playwright-core. Run by tests/replay.test.sh:
//
//   node tests/browser/replay.mjs PAGE.html TRACE.txt SHOTS_DIR
//
// PAGE.html is what `utak --html` wrote for a run, TRACE.txt what the same run
// printed (its "cycle N: ..." lines are the oracle for the page's trace lines).
// Checks: the page loads and runs with no console error and no request beyond the
// file itself; it has one frame per cycle printed, plus the start; stepping with the
// arrow keys shows each cycle's own trace line and its world model's objects (the
// data's own, read apart from the viewer); Home and End and the slider go where
// they say; play advances and pause stops; and screenshots of the TABLE at the first
// and the last frame differ around the square where Utak started and the square where
// he ended. Prints "[PASS] name" / "[FAIL] name: why" per check; exits 1 on a failure.
import { chromium } from "playwright-core";
import { readFileSync } from "node:fs";
import { join, resolve } from "node:path";

const [page_path, trace_path, shots] = process.argv.slice(2);
const executablePath = process.env.CHROMIUM || "/usr/bin/chromium";
const trace = readFileSync(trace_path, "utf8").split("\n").filter((l) => /^cycle \d+: /.test(l));

// The believed objects at each frame, read from the page's data here, apart from the
// viewer: a node the same as one of the frame before is written as its index in that
// frame's list (replay.h, model), and a frame without a model keeps the last one.
const html = readFileSync(page_path, "utf8");
const data = JSON.parse(html.slice(html.indexOf(">", html.indexOf('<script id="utak-replay-data"')) + 1,
                                   html.indexOf("</script>", html.indexOf('<script id="utak-replay-data"'))));
const believed = [];
{
	let before = [], nodes = [];
	for (const fr of data.frames) {
		if (fr.model) {
			nodes = fr.model.nodes.map((n) => (typeof n === "number" ? before[n] : n));
			before = nodes;
		}
		believed.push(nodes.filter((n) => n && n.kind === "object").map((n) => `${n.name} ${n.conf.toFixed(2)}`));
	}
}

let failed = 0;
function check(name, ok, why) {
	if (ok) console.log(`[PASS] ${name}`);
	else {
		failed++;
		console.log(`[FAIL] ${name}: ${why}`);
	}
}

// Headless (playwright's default), with a fresh profile of playwright's making.
const browser = await chromium.launch({
	executablePath,
	args: [
		"--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
		"--disable-background-networking", "--disable-component-update", "--disable-sync",
	],
});
try {
	const context = await browser.newContext({ viewport: { width: 1200, height: 1600 }, deviceScaleFactor: 1 });
	const page = await context.newPage();
	const errors = [], requests = [];
	page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") errors.push(m.text()); });
	page.on("pageerror", (e) => errors.push(String(e)));
	const url = "file://" + resolve(page_path);
	page.on("request", (r) => { if (r.url().split("#")[0] !== url) requests.push(r.url()); });
	await page.goto(url);
	await page.waitForFunction(() => window.utakReplay !== undefined, null, { timeout: 10000 });

	const frames = await page.evaluate(() => window.utakReplay.frames);
	check("one frame per cycle, and the start", frames === trace.length + 1,
	      `${frames} frames for ${trace.length} cycles printed`);
	check("the slider spans the cycles", (await page.getAttribute("#slider", "max")) === String(trace.length),
	      `max ${await page.getAttribute("#slider", "max")}`);

	// Step through every cycle with the right arrow: each shows its own trace line.
	const start_line = await page.textContent("#trace-line");
	let wrong = [], unseen = [];
	for (let k = 1; k <= trace.length; k++) {
		await page.keyboard.press("ArrowRight");
		const line = await page.textContent("#trace-line");
		if (line !== trace[k - 1]) wrong.push(`cycle ${k}: "${line}"`);
		const said = await page.textContent("#i-model"), n = believed[k].length;
		if (!said.includes(`; ${n} object${n === 1 ? "" : "s"}`) || believed[k].some((o) => !said.includes(o)))
			unseen.push(`cycle ${k}: want ${believed[k].join(", ") || "none"}, the page says "${said.split("\n")[1]}"`);
	}
	check("the right arrow steps cycle by cycle, each with its trace line", wrong.length === 0,
	      wrong.slice(0, 3).join("; "));
	check("each cycle's world model shows every object believed then, with its confidence", unseen.length === 0,
	      unseen.slice(0, 3).join("; "));
	await page.keyboard.press("ArrowRight"); // past the end: stays
	check("the right arrow stops at the last cycle",
	      (await page.textContent("#trace-line")) === trace[trace.length - 1], "moved past the end");
	await page.keyboard.press("ArrowLeft");
	check("the left arrow steps back", (await page.textContent("#trace-line")) === trace[trace.length - 2],
	      await page.textContent("#trace-line"));
	await page.keyboard.press("Home");
	check("Home shows the start", (await page.textContent("#trace-line")) === start_line &&
	      (await page.evaluate(() => window.utakReplay.current())) === 0, "not at the start");
	const mid = Math.ceil(trace.length / 2);
	await page.$eval("#slider", (el, v) => { el.value = v; el.dispatchEvent(new Event("input")); }, String(mid));
	check("the slider shows its cycle", (await page.textContent("#trace-line")) === trace[mid - 1],
	      await page.textContent("#trace-line"));
	const label = await page.textContent("#frame-label");
	check("the label names the cycle", label.includes(`cycle ${mid} of ${trace.length}`), label);

	// Play advances, pause stops.
	await page.keyboard.press("Home");
	await page.selectOption("#speed", "250");
	await page.click("#b-play");
	await page.waitForFunction(() => window.utakReplay.current() >= 2, null, { timeout: 5000 });
	await page.click("#b-play");
	const paused_at = await page.evaluate(() => window.utakReplay.current());
	await page.waitForTimeout(700);
	check("play advances and pause stops", paused_at >= 2 &&
	      (await page.evaluate(() => window.utakReplay.current())) === paused_at, `paused at ${paused_at}`);

	// The TABLE at the first and the last frame: where Utak was and where he went.
	async function table_shot(key) {
		await page.keyboard.press(key);
		const png = await page.locator("#c-table").screenshot({ path: shots ? join(shots, `table-${key}.png`) : undefined });
		return png.toString("base64");
	}
	const first = await table_shot("Home"), last = await table_shot("End");
	const spots = await page.evaluate(() => {
		const d = window.utakReplay.data, f0 = d.frames[0].utak, f1 = d.frames[d.frames.length - 1].utak;
		const c = document.getElementById("c-table").getBoundingClientRect();
		const at = (p) => { const q = window.utakReplay.tablePixel(p[0], p[1]); return [q[0] - c.left, q[1] - c.top]; };
		return { start: at(f0), end: at(f1), far: Math.hypot(f1[0] - f0[0], f1[1] - f0[1]) };
	});
	// The screenshots are decoded by the browser itself, then compared in a box of
	// 9 x 9 pixels (under a square at this scale) about each point.
	const diff = await page.evaluate(async ({ a, b, spots }) => {
		async function pixels(b64) {
			const img = new Image();
			img.src = "data:image/png;base64," + b64;
			await img.decode();
			const cv = document.createElement("canvas");
			cv.width = img.width; cv.height = img.height;
			const g = cv.getContext("2d");
			g.drawImage(img, 0, 0);
			return g.getImageData(0, 0, img.width, img.height);
		}
		const A = await pixels(a), B = await pixels(b);
		function changed(p) {
			let n = 0, all = 0;
			for (let y = Math.round(p[1]) - 4; y <= Math.round(p[1]) + 4; y++)
				for (let x = Math.round(p[0]) - 4; x <= Math.round(p[0]) + 4; x++) {
					const i = (y * A.width + x) * 4;
					all++;
					if (Math.abs(A.data[i] - B.data[i]) + Math.abs(A.data[i + 1] - B.data[i + 1]) + Math.abs(A.data[i + 2] - B.data[i + 2]) > 60) n++;
				}
			return n / all;
		}
		return { start: changed(spots.start), end: changed(spots.end), size: [A.width, A.height, B.width, B.height] };
	}, { a: first, b: last, spots });
	check("Utak moved in this run", spots.far > 2, `${spots.far} squares`);
	check("the first and last screenshots differ where Utak started", diff.start > 0.2, JSON.stringify(diff));
	check("the first and last screenshots differ where Utak ended", diff.end > 0.2, JSON.stringify(diff));

	if (shots) await page.screenshot({ path: join(shots, "page-end.png"), fullPage: true });
	check("no console error or warning", errors.length === 0, errors.slice(0, 3).join(" | "));
	check("no request beyond the page itself", requests.length === 0, requests.slice(0, 3).join(" "));
} catch (e) {
	check("the page runs", false, e && e.stack ? e.stack.split("\n").slice(0, 3).join(" ") : String(e));
} finally {
	await browser.close();
}
process.exit(failed ? 1 : 0);
