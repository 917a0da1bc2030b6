// Scores IGC files with igc-xc-score (the reference scorer) and prints one JSON line per file:
// {file, rules, score, type, code, seconds}. Usage: node score.mjs RULES [hp] [notrim] FILE...
import { readFileSync } from 'node:fs';
import IGCParser from 'igc-parser';
import { solver, scoringRules } from 'igc-xc-score';

const names = { xcontest: 'XContest', ffvl: 'FFVL', fai: 'FAI', 'fai-oar': 'FAI-OAR', 'fai-cylinders': 'FAI-Cylinders', xcleague: 'XCLeague' };
const args = process.argv.slice(2);
const rules = args.shift();
let hp = false, trim = true;
if (args[0] === 'hp') { hp = true; args.shift(); }
if (args[0] === 'notrim') { trim = false; args.shift(); }
for (const file of args) {
  const flight = IGCParser.parse(readFileSync(file, 'utf8'), { lenient: true });
  const t0 = process.hrtime.bigint();
  // The solver is a generator; without maxcycle its first result is the final, optimal one.
  const best = solver(flight, scoringRules[names[rules]], { trim, hp }).next().value;
  const seconds = Number(process.hrtime.bigint() - t0) / 1e9;
  console.log(JSON.stringify({ file, rules, score: best.score, type: best.opt.scoring.name, code: best.opt.scoring.code, seconds }));
}
