// esc report: renders the data block of the page (runtime/report/html_report.cpp) with
// Chart.js. Sets document.title to end in " (ready)" once every chart and the first
// replay frame are drawn; errors are shown on the page (see the handler in the page).
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('esc-data').textContent);
  const root = document.getElementById('esc-report');
  const palette = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2',
                   '#7f7f7f', '#bcbd22'];
  const actionPalette = ['#4e79a7', '#f28e2b', '#59a14f', '#e15759', '#76b7b2', '#edc948', '#b07aa1', '#ff9da7',
                         '#9c755f', '#bab0ac'];
  // Collisions: a colour no behavior takes (the palette above, or the hues of choiceColour).
  const collisionColour = '#111111';
  // The colour of choice i of n: the palette for up to 10, else hues spread evenly (the
  // sensitivity experiment's supervisors choose among 24), never black.
  function choiceColour(i, n) {
    if (n <= actionPalette.length) return actionPalette[i % actionPalette.length];
    // HSL to RGB with saturation 0.65 and lightness 0.45 (CSS Color 4's conversion).
    const h = 360 * i / n, s = 0.65, l = 0.45, a = s * Math.min(l, 1 - l);
    const channel = k => {
      const t = (k + h / 30) % 12;
      return Math.round(255 * (l - a * Math.max(-1, Math.min(t - 3, 9 - t, 1)))).toString(16).padStart(2, '0');
    };
    return `#${channel(0)}${channel(8)}${channel(4)}`;
  }
  Chart.defaults.animation = false;          // static plots: screenshots and printing show them whole
  Chart.defaults.maintainAspectRatio = false;

  function el(tag, attrs, children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'text') e.textContent = v; else if (k === 'html') e.innerHTML = v; else e.setAttribute(k, v);
    }
    for (const c of children || []) e.appendChild(c);
    return e;
  }
  function alpha(hex, a) {
    const n = parseInt(hex.slice(1), 16);
    return `rgba(${(n >> 16) & 255},${(n >> 8) & 255},${n & 255},${a})`;
  }
  function fmt(x, d) { return x === null || x === undefined || Number.isNaN(x) ? 'n/a' : Number(x).toFixed(d); }
  // Decimals for fitness values whose largest magnitude is `largest`: `least` down to 1, below
  // it three significant digits (a maze's -0.0123 m, not -0.0), as the end table's.
  function fitnessDecimals(largest, least) {
    const m = Math.abs(largest);
    return !(m < 1) || m === 0 ? least : Math.max(least, Math.min(10, 2 - Math.floor(Math.log10(m))));
  }
  function percent(x) { const t = fmt(x, 0); return t === 'n/a' ? t : `${t}%`; }
  function fmtP(p) {
    if (p === null || p === undefined) return 'n/a';
    return p < 1e-4 ? p.toExponential(1) : p.toFixed(4);
  }
  function meanSd(values) {
    const n = values.length;
    if (n === 0) return [NaN, NaN];
    const m = values.reduce((a, b) => a + b, 0) / n;
    const v = n > 1 ? values.reduce((a, b) => a + (b - m) * (b - m), 0) / (n - 1) : 0;
    return [m, Math.sqrt(v)];
  }
  // "1 epoch", "3 epochs".
  function counted(n, noun) { return `${n} ${noun}${n === 1 ? '' : 's'}`; }
  function quantile(sorted, q) {            // linear interpolation (numpy's default)
    if (sorted.length === 0) return NaN;
    const pos = (sorted.length - 1) * q;
    const lo = Math.floor(pos), hi = Math.ceil(pos);
    return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo);
  }
  function chartCard(parent, title, note) {
    const canvas = el('canvas');
    const card = el('div', {class: 'card'}, [el('h3', {text: title}), el('div', {class: 'chart'}, [canvas])]);
    if (note) card.appendChild(el('p', {class: 'note', text: note}));
    parent.appendChild(card);
    return canvas;
  }

  // Mean over runs, per generation, of one per-run series ("best" or "mean"), with +-sd
  // (computed by esc over the runs that reached each generation: html_report.cpp).
  function curves(controller, key) {
    const {mean, sd} = controller.curves[key];
    const lo = mean.map((m, g) => m === null ? null : m - sd[g]);
    const hi = mean.map((m, g) => m === null ? null : m + sd[g]);
    return {mean, lo, hi, length: mean.length};
  }

  function fitnessChart(parent, exp, key, title) {
    const datasets = [];
    let length = 0;
    exp.controllers.forEach((c, i) => {
      if (c.runs.length === 0) return;
      const col = palette[i % palette.length];
      const cv = curves(c, key);
      length = Math.max(length, cv.length);
      // The band: upper bound filled down to the lower bound (the next dataset).
      datasets.push({label: `${c.name} +sd`, data: cv.hi, borderWidth: 0, pointRadius: 0, fill: '+1',
                     backgroundColor: alpha(col, 0.15), escBand: true});
      datasets.push({label: `${c.name} -sd`, data: cv.lo, borderWidth: 0, pointRadius: 0, fill: false,
                     escBand: true});
      datasets.push({label: c.name, data: cv.mean, borderColor: col, backgroundColor: col, borderWidth: 2,
                     pointRadius: 0, fill: false});
    });
    const labels = Array.from({length}, (_, g) => g);   // generation 0: the initial population
    return new Chart(chartCard(parent, title, 'Line: mean over runs; band: ± one standard deviation across runs.'), {
      type: 'line',
      data: {labels, datasets},
      options: {
        interaction: {mode: 'index', intersect: false},
        plugins: {legend: {labels: {filter: item => !datasets[item.datasetIndex].escBand}},
                  tooltip: {filter: item => !datasets[item.datasetIndex].escBand}},
        scales: {x: {title: {display: true, text: 'generation'}}, y: {title: {display: true, text: 'fitness'}}},
      },
    });
  }

  // Box plot of the runs' best fitness: whisker (min..max) and box (Q1..Q3) as floating
  // bars, the median as a line marker, every run as a dot.
  function boxChart(parent, exp) {
    const cs = exp.controllers.filter(c => c.runs.length > 0);
    const labels = cs.map(c => c.name);
    const whisker = [], box = [], median = [], dots = [];
    cs.forEach(c => {
      const v = c.runs.map(r => r.best_fitness).sort((a, b) => a - b);
      whisker.push([v[0], v[v.length - 1]]);
      box.push([quantile(v, 0.25), quantile(v, 0.75)]);
      median.push({x: c.name, y: quantile(v, 0.5)});
      v.forEach(y => dots.push({x: c.name, y}));
    });
    const colors = cs.map(c => palette[exp.controllers.indexOf(c) % palette.length]);
    return new Chart(chartCard(parent, 'Best fitness of each run',
                               'Box: quartiles; whiskers: lowest and highest run; bar: median; dots: runs.'), {
      type: 'bar',
      data: {
        labels,
        datasets: [
          {label: 'range', data: whisker, backgroundColor: '#555', barPercentage: 0.03, categoryPercentage: 1, grouped: false},
          {label: 'Q1–Q3', data: box, backgroundColor: colors.map(c => alpha(c, 0.35)), borderColor: colors,
           borderWidth: 1.5, barPercentage: 0.5, categoryPercentage: 1, grouped: false},
          {type: 'scatter', label: 'median', data: median, pointStyle: 'line', pointRadius: 28, borderWidth: 3,
           borderColor: '#111', backgroundColor: '#111'},
          {type: 'scatter', label: 'runs', data: dots, pointRadius: 3, backgroundColor: 'rgba(0,0,0,0.55)',
           borderColor: 'rgba(0,0,0,0)'},
        ],
      },
      options: {
        plugins: {legend: {display: false}},
        // On the data's own scale: fitness need not start at 0.
        scales: {x: {type: 'category', labels},
                 y: {beginAtZero: false, grace: '5%', title: {display: true, text: 'best fitness'}}},
      },
    });
  }

  function statsTables(parent, exp) {
    const card = el('div', {class: 'card'});
    card.appendChild(el('h3', {text: 'Best fitness over runs'}));
    const t = el('table');
    t.appendChild(el('tr', {}, ['controller', 'runs', 'mean', 'sd', 'median', 'best', 'worst']
      .map(h => el('th', {text: h}))));
    for (const s of exp.stats.summary) {
      const d = fitnessDecimals(Math.max(Math.abs(s.best), Math.abs(s.worst), s.sd), 2);
      t.appendChild(el('tr', {}, [s.controller, String(s.n), fmt(s.mean, d), fmt(s.sd, d), fmt(s.median, d),
                                  fmt(s.best, d), fmt(s.worst, d)].map(v => el('td', {text: v}))));
    }
    card.appendChild(t);
    parent.appendChild(card);
    // The comparisons' tables are wider than half a window: a card across the grid's row.
    const compared = el('div', {class: 'card wide'});
    pairsTable(compared, exp.stats.pairs, r => `${r.a} vs ${r.b}`, 'the pairs of this table');
    if (exp.success) {
      compared.appendChild(el('h3', {text: `Success: ${exp.success.test}`}));
      const s = el('table');
      s.appendChild(el('tr', {}, ['controller', 'successes', 'runs', 'median evaluations to success']
        .map(h => el('th', {text: h}))));
      for (const c of exp.success.controllers)
        s.appendChild(el('tr', {}, [c.controller, String(c.successes), String(c.runs), evaluations(c.median_evaluations)]
          .map(v => el('td', {text: v}))));
      compared.appendChild(s);
      successPairsTable(compared, exp.success.pairs, r => `${r.a} vs ${r.b}`, 'the pairs of this table');
    }
    if (compared.children.length > 0) parent.appendChild(compared);
  }

  // "3/40 (1250)": runs that succeeded, of all, and the median of their evaluations to success.
  function successText(s) {
    return `${s.successes}/${s.runs} (${s.median_evaluations === null ? '–' : evaluations(s.median_evaluations)})`;
  }

  // A count of evaluations, or a median of them (7950, 3945.5), as the end table prints it.
  function evaluations(x) { return x === null || x === undefined || Number.isNaN(x) ? 'n/a' : String(x); }

  // Success compared, pair by pair: Fisher's exact test of the counts, the censored
  // Mann-Whitney test of the evaluations to success; each one Holm family.
  function successPairsTable(card, pairs, label, family) {
    if (!pairs || pairs.length === 0) return;
    card.appendChild(el('h3', {text: 'Success compared (two-sided)'}));
    const p = el('table');
    p.appendChild(el('tr', {}, ['pair', 'successes', 'Fisher p', 'p Holm', 'odds ratio', 'Mann-Whitney U (censored)',
                                'p', 'p Holm', 'censored at'].map(h => el('th', {text: h}))));
    for (const r of pairs) {
      const row = el('tr', {}, [label(r), `${r.successes_a}/${r.runs_a} vs ${r.successes_b}/${r.runs_b}`,
                                fmtP(r.fisher_p), fmtP(r.fisher_p_holm),
                                r.odds_ratio === 'inf' ? '∞' : fmt(r.odds_ratio, 2), fmt(r.censored_u, 1),
                                fmtP(r.censored_p), fmtP(r.censored_p_holm),
                                r.runs_a + r.runs_b === 0 ? 'n/a' : r.censored_at === null ? 'none' : fmt(r.censored_at, 0)]
        .map(v => el('td', {text: v})));
      if (r.fisher_p_holm !== null && r.fisher_p_holm < 0.05) row.children[3].className = 'significant';
      if (r.censored_p_holm !== null && r.censored_p_holm < 0.05) row.children[7].className = 'significant';
      p.appendChild(row);
    }
    card.appendChild(p);
    card.appendChild(el('p', {class: 'note', text:
      'Fisher: Fisher\'s exact test of the success counts; odds ratio: the odds of success of the first over the ' +
      'second. Mann-Whitney U (censored): the evaluations up to the first success, where a run that never ' +
      'succeeded counts as more than the budget, tied above every success (Gehan\'s test); censored at: what such ' +
      `a run counts as, the pair's largest budget + 1. Holm: p adjusted over ${family}, for each test; bold: ` +
      'adjusted p < 0.05. n/a: the test is undefined for these samples.'}));
  }

  // Pairwise comparisons, one Holm family: `label` names each row, `family` what it holds.
  function pairsTable(card, pairs, label, family) {
    if (pairs.length === 0) return;
    card.appendChild(el('h3', {text: 'Pairwise comparisons (two-sided)'}));
    const p = el('table');
    p.appendChild(el('tr', {}, ['pair', 'Welch t', 'df', 'Welch p', 'p Holm', 'Mann-Whitney U', 'Mann-Whitney p',
                                'p Holm', 'A12', 'sd ratio', 'Brown-Forsythe p', 'p Holm'].map(h => el('th', {text: h}))));
    for (const r of pairs) {
      const row = el('tr', {}, [label(r), fmt(r.welch_t, 3), fmt(r.welch_df, 1), fmtP(r.welch_p),
                                fmtP(r.welch_p_holm), fmt(r.mwu_u, 1), fmtP(r.mwu_p) + (r.mwu_exact ? ' (exact)' : ''),
                                fmtP(r.mwu_p_holm), fmt(r.a12, 2), fmt(r.sd_ratio, 2), fmtP(r.bf_p),
                                fmtP(r.bf_p_holm)].map(v => el('td', {text: v})));
      if (r.welch_p_holm !== null && r.welch_p_holm < 0.05) row.children[4].className = 'significant';
      if (r.mwu_p_holm !== null && r.mwu_p_holm < 0.05) row.children[7].className = 'significant';
      if (r.bf_p_holm !== null && r.bf_p_holm < 0.05) row.children[11].className = 'significant';
      p.appendChild(row);
    }
    card.appendChild(p);
    card.appendChild(el('p', {class: 'note', text:
      'Welch: t-test with unequal variances. Mann-Whitney: exact when a sample has at most 8 runs and there are ' +
      'no ties, else the normal approximation with tie and continuity corrections (as SciPy\'s method "auto"). ' +
      `Holm: p adjusted over ${family}, for each test; bold: adjusted p < 0.05. A12: Vargha-Delaney ` +
      'effect size, the chance that a run of the first beats a run of the second (0.5: no effect). sd ratio: sd of ' +
      'the first over sd of the second. Brown-Forsythe: test of equal spread (Levene\'s test about the medians). ' +
      'n/a: the test ' +
      'is undefined for these samples.'}));
  }

  // The SVG figures (the same as the files in figures/), one card each.
  function figures(parent, list) {
    for (const f of list || []) {
      const card = el('div', {class: 'card figure'}, [el('div', {class: 'svg', html: f.svg})]);
      card.appendChild(el('p', {class: 'note', text: `figures/${f.file}`}));
      parent.appendChild(card);
    }
  }

  // A study: its conditions, the table of conditions by controllers, one family of
  // comparisons, and its figures.
  function studySection(study) {
    const section = el('section');
    section.appendChild(el('h1', {text: `Study ${study.name}`}));
    section.appendChild(el('p', {class: 'meta', text:
      `${study.conditions.length} conditions, master seed ${study.seed} (every condition's)` +
      (study.directory ? `; directory ${study.directory}` : '')}));
    const conditions = el('table');
    conditions.appendChild(el('tr', {}, ['condition', 'experiment', 'settings', 'status'].map(h => el('th', {text: h}))));
    for (const c of study.conditions)
      conditions.appendChild(el('tr', {}, [c.name, c.experiment,
        Object.entries(c.settings).map(([k, v]) => `${k} ${v}`).join(', ') || '(as declared)', c.status]
        .map(v => el('td', {text: v}))));
    section.appendChild(el('div', {class: 'card'}, [conditions]));
    section.appendChild(el('h2', {text: 'Final results and statistics'}));
    const card = el('div', {class: 'card'});
    card.appendChild(el('h3', {text: 'Best fitness of each run: mean ± sd (median)'}));
    const t = el('table');
    t.appendChild(el('tr', {}, ['condition'].concat(study.controllers).map(h => el('th', {text: h}))));
    for (const c of study.conditions)
      t.appendChild(el('tr', {}, [c.name].concat(study.controllers.map(k => {
        const cell = study.cells.find(x => x.condition === c.name && x.controller === k);
        if (!cell || cell.n === 0) return '–';
        const d = fitnessDecimals(Math.max(Math.abs(cell.mean), Math.abs(cell.median), cell.sd), 1);
        return `${fmt(cell.mean, d)} ± ${fmt(cell.sd, d)} (${fmt(cell.median, d)})`;
      })).map(v => el('td', {text: v}))));
    card.appendChild(t);
    pairsTable(card, study.pairs, r => r.label, `the ${study.pairs.length} comparisons of this table (${study.family})`);
    if (study.cells.some(x => x.success)) {
      const tests = [...new Set(study.conditions.filter(c => c.success).map(c => c.success))];
      card.appendChild(el('h3', {text: tests.length === 1 ? `Success: ${tests[0]}` : 'Success (each condition\'s test)'}));
      card.appendChild(el('p', {class: 'note', text:
        'Runs that succeeded, of all, and the median of their evaluations up to the first success.'}));
      const s = el('table');
      s.appendChild(el('tr', {}, ['condition'].concat(study.controllers).map(h => el('th', {text: h}))));
      for (const c of study.conditions)
        s.appendChild(el('tr', {}, [tests.length === 1 || !c.success ? c.name : `${c.name} (${c.success})`]
          .concat(study.controllers.map(k => {
            const cell = study.cells.find(x => x.condition === c.name && x.controller === k);
            return cell && cell.success ? successText(cell.success) : '–';
          })).map(v => el('td', {text: v}))));
      card.appendChild(s);
      successPairsTable(card, study.success_pairs, r => r.label,
                        `the ${(study.success_pairs || []).length} comparisons of this table (${study.family})`);
    }
    section.appendChild(card);
    section.appendChild(el('h2', {text: 'Figures'}));
    const grid = el('div', {class: 'figures'});
    section.appendChild(grid);
    figures(grid, study.figures);
    return section;
  }

  function usageChart(parent, c, color) {
    // Fraction of the best evaluation's steps on which each behavior acted, mean over runs.
    const fractions = c.actions.map((_, a) => meanSd(c.usage.map(u => {
      const total = u.reduce((x, y) => x + y, 0);
      return total > 0 ? u[a] / total : 0;
    }))[0]);
    return new Chart(chartCard(parent, `Behavior usage: ${c.name}`,
                               'Share of control steps on which each behavior acted during the best evaluation ' +
                               'of each run (mean over runs).'), {
      type: 'bar',
      data: {labels: c.actions, datasets: [{label: c.name, data: fractions.map(f => 100 * f),
                                            backgroundColor: c.actions.map((_, i) => choiceColour(i, c.actions.length))}]},
      options: {plugins: {legend: {display: false}},
                scales: {y: {min: 0, max: 100, title: {display: true, text: '% of steps'}}}},
    });
  }

  // The lines of the paper's Figure 2 for a controller, as the SVG figure groups them
  // (usage_figure.cpp, sent as `usage_panels`): a colour per behavior, or per library when a
  // panel's lines are libraries.
  function usagePanels(c) {
    return c.usage_panels.map(p => ({
      title: p.title,
      lines: p.lines.map((line, k) => ({
        label: line.label, indices: line.indices,
        colour: p.by_library ? choiceColour(k, p.lines.length) : choiceColour(line.indices[0], c.actions.length)})),
    }));
  }

  // The median over runs, per generation, of a line's calls per 10,000 steps, with the
  // quartiles (as usage_figure.cpp: calls are skewed, a mean +-sd band was not readable).
  function usageCurve(c, line, key) {
    const runs = c.usage_generations;
    const length = Math.max(0, ...runs.map(r => r[key].length));
    const median = [], lo = [], hi = [];
    for (let g = 0; g < length; ++g) {
      const values = runs.filter(r => g < r[key].length && r[key][g] !== null)
                         .map(r => line.indices.reduce((sum, i) => sum + r[key][g][i], 0))
                         .sort((a, b) => a - b);
      median.push(values.length ? quantile(values, 0.5) : null);
      lo.push(values.length ? quantile(values, 0.25) : null);
      hi.push(values.length ? quantile(values, 0.75) : null);
    }
    return {median, lo, hi, length};
  }

  // Figure 2: how often each behavior is called (per 10,000 steps) as generations go by.
  function usageOverGenerations(parent, c) {
    const panels = usagePanels(c);
    const which = el('select');
    [['best', 'best evaluation of each generation'], ['mean', 'mean over each generation\'s evaluations']]
      .forEach(([v, t]) => which.appendChild(el('option', {value: v, text: t})));
    const charts = [];
    const datasetsOf = (panel, key) => {
      const datasets = [];
      for (const line of panel.lines) {
        const cv = usageCurve(c, line, key);
        datasets.push({label: `${line.label} q3`, data: cv.hi, borderWidth: 0, pointRadius: 0, fill: '+1',
                       backgroundColor: alpha(line.colour, 0.15), escBand: true});
        datasets.push({label: `${line.label} q1`, data: cv.lo, borderWidth: 0, pointRadius: 0, fill: false, escBand: true});
        datasets.push({label: line.label, data: cv.median, borderColor: line.colour, backgroundColor: line.colour,
                       borderWidth: 2, pointRadius: 0, fill: false});
      }
      return datasets;
    };
    panels.forEach((panel, k) => {
      const datasets = datasetsOf(panel, 'best');
      const length = Math.max(0, ...c.usage_generations.map(r => r.best.length));
      const canvas = chartCard(parent, `Calls per 10,000 steps: ${c.name}, ${panel.title}`,
                               'Line: median over runs; band: from the first to the third quartile. ' +
                               'Calls: steps on which the behavior acted, scaled to 10,000 steps.');
      if (k === 0) canvas.parentElement.parentElement.insertBefore(
        el('div', {class: 'controls'}, [el('span', {text: 'usage in the'}), which]), canvas.parentElement);
      charts.push({panel, chart: new Chart(canvas, {
        type: 'line',
        data: {labels: Array.from({length}, (_, g) => g), datasets},
        options: {
          interaction: {mode: 'index', intersect: false},
          plugins: {legend: {labels: {filter: (item, data) => !data.datasets[item.datasetIndex].escBand}},
                    tooltip: {filter: item => !item.dataset.escBand}},
          scales: {x: {title: {display: true, text: 'generation'}},
                   y: {min: 0, title: {display: true, text: 'calls per 10,000 steps'}}},
        },
      })});
    });
    which.addEventListener('change', () => charts.forEach(({panel, chart}) => {
      chart.data.datasets = datasetsOf(panel, which.value);
      chart.update();
    }));
  }

  // Controllers carried into a new setting: their fitness in the origin experiment, here,
  // the change, and (start from) when each run regained the origin's level.
  function transfersCard(parent, exp) {
    const cs = exp.controllers.filter(c => c.transfers);
    if (cs.length === 0) return;
    const first = cs[0].transfers;
    const card = el('div', {class: 'card'});
    card.appendChild(el('h3', {text: `From experiment ${first.origin}`}));
    const t = el('table');
    const head = ['controller', 'fitness there', 'fitness here', 'change'];
    if (!first.evaluate_only) head.push('best here', 'loss made up', 'regained', 'median generation');
    t.appendChild(el('tr', {}, head.map(h => el('th', {text: h}))));
    for (const c of cs) {
      const s = c.transfers;
      const cells = [c.name, fmt(s.origin_mean, 1), fmt(s.here_mean, 1),
                     s.change_mean === null ? 'n/a' : `${s.change_mean > 0 ? '+' : ''}${fmt(s.change_mean, 1)}%`];
      if (!s.evaluate_only)
        cells.push(fmt(s.best_here_mean, 1), percent(s.loss_regained_pooled),
                   `${s.regained} of ${s.runs.length} runs`, fmt(s.regained_median, 0));
      t.appendChild(el('tr', {}, cells.map(v => el('td', {text: v}))));
    }
    card.appendChild(t);
    const runs = el('table');
    const runHead = ['controller', 'run', 'from run', 'fitness there', 'fitness here', 'change'];
    if (!first.evaluate_only) runHead.push('best here', 'loss made up', 'regained at generation');
    runs.appendChild(el('tr', {}, runHead.map(h => el('th', {text: h}))));
    for (const c of cs)
      for (const r of c.transfers.runs) {
        const cells = [c.name, String(r.run), String(r.origin_run), fmt(r.origin_fitness, 1), fmt(r.fitness_here, 1),
                       r.change_percent === null ? 'n/a' : `${r.change_percent > 0 ? '+' : ''}${fmt(r.change_percent, 1)}%`];
        if (!c.transfers.evaluate_only)
          cells.push(fmt(r.best_here, 1), percent(r.loss_regained),
                     r.regained_at === null ? 'never' : String(r.regained_at));
        runs.appendChild(el('tr', {}, cells.map(v => el('td', {text: v}))));
      }
    card.appendChild(el('h3', {text: 'Per run'}));
    card.appendChild(runs);
    card.appendChild(el('p', {class: 'note', text:
      'Fitness there: the best fitness of the origin run whose best genome this run took. Fitness here: that genome ' +
      'evaluated here (individual 0 of generation 0). Change: (here - there) / |there|. Best here: the run\'s ' +
      'best fitness over its generations here. Loss made up: (best here - fitness here) / (there - fitness here), ' +
      'for runs whose genome lost fitness here (100%: back at the origin\'s level; the controller\'s line pools ' +
      'the runs: their gains summed over their losses summed). Best here is the highest of many noisy ' +
      'evaluations, so it leans high. Regained: the first ' +
      'generation whose best fitness reaches the origin\'s.'}));
    parent.appendChild(card);
  }

  // The replay: the arena drawn to scale, the trajectory so far, the robot with its
  // heading and IR rays, and per step the IR readings, commands and acting behavior.
  function replay(parent, exp) {
    const withReplay = exp.controllers.filter(c => c.replay && c.replay.rows.length > 0);
    if (withReplay.length === 0) return;
    const card = el('div', {class: 'card'});
    card.appendChild(el('h3', {text: 'Replay of the best controllers'}));
    const select = el('select');
    const watch = el('select');   // which robot of a group the bars show
    withReplay.forEach((c, i) => select.appendChild(el('option', {value: String(i), text: `${c.name} (run ${c.replay.run}, fitness ${fmt(c.replay.fitness, fitnessDecimals(c.replay.fitness, 2))})`})));
    const play = el('button', {text: 'Pause'});
    const slider = el('input', {type: 'range', min: '0', max: '0', value: '0'});
    const speed = el('select');
    [['1', '1x (real time)'], ['4', '4x'], ['16', '16x']].forEach(([v, t]) => speed.appendChild(el('option', {value: v, text: t})));
    speed.value = '4';
    const canvas = el('canvas', {class: 'arena', width: '560', height: '560'});
    const action = el('span', {class: 'action'});
    const readout = el('div', {class: 'readout'});
    // Bars of one sensor array (or the accumulator): fill and value per sensor.
    function bars(labels, kind) {
      const box = el('div', {class: 'irbars'});
      const fill = [], text = [], names = [];
      labels.forEach(label => {
        const f = el('div', {class: kind}), t = el('span'), n = el('span', {text: label});
        fill.push(f); text.push(t); names.push(n);
        box.appendChild(n);
        box.appendChild(el('div', {class: 'irbar'}, [f]));
        box.appendChild(t);
      });
      // Fewer values than bars (a robot whose body has fewer sensors than the group's widest):
      // the rest are shown empty, with a dash.
      return {box, show(values) {
        fill.forEach((f, i) => {
          const v = values[i];
          f.style.width = v === undefined ? '0%' : `${Math.round(100 * v)}%`;
          text[i].textContent = v === undefined ? '–' : v.toFixed(2);
        });
      }, relabel(label) { names.forEach((n, i) => { n.textContent = label(i); }); }};
    }
    // The body and its IR sensors as the stored settings give them ("[(1.18 rad, 1.57 rad), (0.2
    // rad, 0 rad, 0.035 m)]", an outline "[(-0.03 m, -0.055 m), ...]"): mount bearing, axis and
    // distance (rim when absent), in radians and millimetres. A run stored before a robot's
    // sensors were settings has the Khepera's (the report's own arrays) and the disc.
    // A group of several bodies lists them in robot order ("khepera x 2, epuck x 3"), and a
    // further body's setting is `bodyK.KEY` where it differs from the first's `robot.KEY`:
    // each robot is drawn with its own body, and the bars show the watched robot's sensors
    // (bodies with a network each may have other numbers of them).
    const tuples = text => (text.match(/\(([^)]*)\)/g) || []).map(t => t.slice(1, -1).split(',').map(parseFloat));
    const settings = exp.settings || {};
    const listed = (settings.bodies || '').split(', ').map(b => b.match(/^(.*) x ([0-9]+)$/)).filter(m => m);
    const robotBody = listed.flatMap(([, , count], b) => Array(Number(count)).fill(b));
    const setting = (b, key) => settings[`body${b + 1}.${key}`] ?? settings[`robot.${key}`];
    const shapes = (listed.length > 0 ? listed : [null]).map((_, b) => {
      const radius = settings[`body${b + 1}.body_radius`];
      const mounts = setting(b, 'ir_sensors');
      return {
        rr: radius === undefined ? exp.robot_radius_mm : parseFloat(radius) * 1000,
        irMounts: mounts !== undefined
          ? tuples(mounts).map(([b, f, d]) => ({ b, f, mm: d === undefined ? null : d * 1000 }))
          : exp.ir_mount_deg.map((b, i) => ({ b: b * Math.PI / 180, f: exp.ir_facing_deg[i] * Math.PI / 180, mm: null })),
        outlineMm: tuples(setting(b, 'body_outline') || '').map(([px, py]) => [px * 1000, py * 1000]),
        rangeAngles: (setting(b, 'rangefinders') || '').match(/-?[0-9.]+(e[-+]?[0-9]+)?(?= rad)/g),
        // How many rangefinders and radars the body has, where its settings say (older runs
        // do not: then every column the replay holds is the robot's).
        ranges: setting(b, 'rangefinders') === undefined ? undefined
          : ((setting(b, 'rangefinders') || '').match(/ rad/g) || []).length,
        radars: setting(b, 'radars') === undefined ? undefined : parseInt(setting(b, 'radars'), 10),
        rangeMm: parseFloat(setting(b, 'rangefinder_range')) * 1000,
      };
    });
    const shapeOf = k => shapes[robotBody[k] ?? 0];
    const robotLabel = k => listed.length > 1 ? `robot ${k + 1} (${listed[robotBody[k] ?? 0][1]})` : `robot ${k + 1}`;
    const irMounts = shapes.reduce((most, b) => (b.irMounts.length > most.length ? b.irMounts : most), shapes[0].irMounts);
    // The IR sensors as the watched robot's body names them (`IR` for `ir`).
    const irName = b => { const n = setting(b, 'ir_name') || 'ir'; return n === 'ir' ? 'IR' : n; };
    const irs = bars(irMounts.map((_, i) => `${irName(0)} ${i}`), 'ir');
    const lights = bars(irMounts.map((_, i) => `light ${i}`), 'light');
    const accumulator = bars(['energy'], 'energy');
    // The maze navigator's rangefinders and goal radars, where the robot has them (their
    // readings follow the lights in each row). The angles are the stored setting's, as
    // `esc` prints it ("[-1.5707963267948966 rad, ...]"); without it, no rays are drawn.
    const columns = withReplay[0].replay.columns;
    const rangeAt = columns.indexOf('range'), radarAt = columns.indexOf('radar');
    const first = withReplay[0].replay.rows[0];
    const rangeCount = rangeAt >= 0 ? first[rangeAt].length : 0, radarCount = radarAt >= 0 ? first[radarAt].length : 0;
    // Labelled by angle where every body has the first's angles, else by number.
    const rangeAngles = shapes.every(b => String(b.rangeAngles) === String(shapes[0].rangeAngles)) ? shapes[0].rangeAngles : null;
    const rangeLabel = i => rangeAngles && rangeAngles.length === rangeCount
      ? `${Math.round(parseFloat(rangeAngles[i]) * 180 / Math.PI)}°` : `range ${i}`;
    const ranges = bars([...Array(rangeCount).keys()].map(rangeLabel), 'range');
    const radars = bars([...Array(radarCount).keys()].map(i => `${Math.round(360 * i / radarCount)}°`), 'radar');
    const legend = el('div', {class: 'legend'});
    card.appendChild(el('div', {class: 'controls'}, [select, watch, play, el('span', {text: 'speed'}), speed, slider]));
    const navigation = [];
    if (rangeCount > 0) navigation.push(el('h3', {text: 'Rangefinders (distance / range, by angle from the heading)'}), ranges.box);
    if (radarCount > 0) navigation.push(el('h3', {text: 'Goal radars (by slice centre, counter-clockwise from ahead)'}), radars.box);
    // Light sensors read 0 in an arena without lights: their bars only where there are some, or
    // where a robot gives off light (`emission`, a further body's `bodyK.emission`).
    const emitting = Object.entries(settings).some(([k, v]) => /^(robot|body\d+)\.emission$/.test(k) && parseFloat(v) > 0);
    const lit = (exp.arena.lights || []).length > 0 || emitting ? [el('h3', {text: 'Light sensors'}), lights.box] : [];
    card.appendChild(el('div', {class: 'replay'}, [el('div', {}, [canvas, legend]), el('div', {}, [
      el('div', {}, [el('span', {text: 'acting: '}), action]), ...navigation, el('h3', {text: 'IR sensors'}), irs.box,
      ...lit, el('h3', {text: 'Accumulator'}), accumulator.box, el('h3', {text: 'State'}), readout])]));
    const note = el('p', {class: 'note'});
    card.appendChild(note);
    parent.appendChild(card);

    const arena = exp.arena;
    const ctx = canvas.getContext('2d');
    // A group's rows are a row per robot per step (robot order), each ending with its robot:
    // `index` counts steps, and the bars and the readout follow the robot `watched`.
    let c = withReplay[0], rows = c.replay.rows, index = 0, playing = true, last = null, carry = 0;
    let robots = 1, watched = 0;
    watch.addEventListener('change', () => { watched = Number(watch.value); draw(); });
    const margin = 12;
    const scale = Math.min((canvas.width - 2 * margin) / (arena.width * 1000), (canvas.height - 2 * margin) / (arena.height * 1000));
    canvas.height = Math.ceil(arena.height * 1000 * scale + 2 * margin);
    const X = x => margin + x * scale;                               // mm -> px; y up in the arena
    const Y = y => canvas.height - margin - y * scale;

    function choose(i) {
      c = withReplay[i];
      rows = c.replay.rows;
      robots = c.replay.robots || 1;
      index = 0;
      watched = 0;
      watch.innerHTML = '';
      for (let k = 0; k < robots; ++k) watch.appendChild(el('option', {value: String(k), text: robotLabel(k)}));
      watch.style.display = robots > 1 ? '' : 'none';
      slider.max = String(rows.length / robots - 1);
      const shown = rows.length / robots < c.replay.total_steps
        ? `the first ${rows[rows.length - 1][0] + 1} of ${counted(c.replay.total_epochs, 'epoch')} ` +
          `(${rows.length / robots} of ${counted(c.replay.total_steps, 'step')})`
        : c.replay.total_epochs === 1 ? `its one epoch (${counted(rows.length / robots, 'step')})`
                                      : `all ${c.replay.total_epochs} epochs (${counted(rows.length / robots, 'step')})`;
      note.textContent = `Run ${c.replay.run}, evaluation seed ${c.replay.seed}: ${shown}. ` + (robots > 1
        ? `A group of ${robots} robots, each path in its robot's colour; the sensors shown are the chosen robot's; black dots: collisions.`
        : 'Trajectory coloured by the acting action or behavior (symbolic heads, supervisors); black dots: collisions.');
      legend.innerHTML = '';
      const swatch = (colour, label, dot) => legend.appendChild(el('span', {class: 'swatch'}, [
        el('span', {class: dot ? 'dot' : 'line', style: `background:${colour}`}), el('span', {text: label})]));
      if (robots > 1) for (let k = 0; k < robots; ++k) swatch(choiceColour(k, robots), robotLabel(k), false);
      else if (c.actions.length === 0) swatch('#1f77b4', 'path (a classical head chooses no behavior)', false);
      else c.actions.forEach((name, i) => swatch(choiceColour(i, c.actions.length), name, false));
      swatch(collisionColour, 'collision', true);
      draw();
    }
    // Robot `k` of the step's rows as `row` has it: its disc or outline (a group's robot in its
    // colour, the watched one outlined thicker), its heading, its IR sensors (where they sit
    // and where they look) and a navigator's radar slice and rangefinder rays.
    function drawRobot(row, k) {
      const [, , x, y, heading, ir, , , , , collided] = row;
      const { rr, irMounts, outlineMm, rangeAngles, rangeMm } = shapeOf(k);
      ctx.fillStyle = collided ? 'rgba(214,39,40,0.35)' : robots > 1 ? alpha(choiceColour(k, robots), 0.35) : 'rgba(31,119,180,0.25)';
      ctx.strokeStyle = '#1d2330'; ctx.lineWidth = robots > 1 && k === watched ? 3 : 1.5;
      ctx.beginPath();
      if (outlineMm.length >= 3) {
        const c = Math.cos(heading), s = Math.sin(heading);
        outlineMm.forEach(([px, py], i) => {
          const vx = X(x + c * px - s * py), vy = Y(y + s * px + c * py);
          if (i === 0) ctx.moveTo(vx, vy); else ctx.lineTo(vx, vy);
        });
        ctx.closePath();
      } else {
        ctx.arc(X(x), Y(y), rr * scale, 0, 2 * Math.PI);
      }
      ctx.fill(); ctx.stroke();
      ctx.beginPath(); ctx.moveTo(X(x), Y(y));
      ctx.lineTo(X(x + rr * Math.cos(heading)), Y(y + rr * Math.sin(heading))); ctx.stroke();
      for (let i = 0; i < irMounts.length && i < ir.length; ++i) {
        const m = heading + irMounts[i].b, f = heading + irMounts[i].f, at = irMounts[i].mm ?? rr;
        const sx = x + at * Math.cos(m), sy = y + at * Math.sin(m);
        const len = 6 + 30 * ir[i];
        ctx.strokeStyle = alpha('#d9822b', 0.25 + 0.75 * ir[i]); ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(X(sx), Y(sy));
        ctx.lineTo(X(sx + len * Math.cos(f)), Y(sy + len * Math.sin(f))); ctx.stroke();
      }
      // The radar slice holding the goal, as a faint wedge, and each rangefinder's ray up to
      // what it reads (its full range, fainter, when nothing is within it).
      if (radarCount > 0) {
        const slice = row[radarAt].indexOf(1), half = Math.PI / radarCount;
        if (slice >= 0) {
          const mid = heading + 2 * half * slice;
          ctx.fillStyle = 'rgba(197,27,125,0.12)';
          ctx.beginPath(); ctx.moveTo(X(x), Y(y));
          ctx.arc(X(x), Y(y), 3 * rr * scale, -(mid + half), -(mid - half)); ctx.closePath(); ctx.fill();
        }
      }
      if (rangeCount > 0) {
        if (rangeAngles && rangeAngles.length === rangeCount && rangeMm > 0)
          row[rangeAt].forEach((v, i) => {
            const a = heading + parseFloat(rangeAngles[i]), len = v * rangeMm;
            ctx.strokeStyle = alpha('#17becf', v < 1 ? 0.9 : 0.3); ctx.lineWidth = 1.5;
            ctx.beginPath(); ctx.moveTo(X(x), Y(y)); ctx.lineTo(X(x + len * Math.cos(a)), Y(y + len * Math.sin(a))); ctx.stroke();
          });
      }
    }
    function draw() {
      const r = rows[index * robots + watched];
      const [epoch, step, x, y, heading, ir, left, right, act, fitness, collided, energy, light] = r;
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.fillStyle = '#fbfbf8';
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      ctx.strokeStyle = '#333'; ctx.lineWidth = 3;
      ctx.strokeRect(X(0), Y(arena.height * 1000), arena.width * 1000 * scale, arena.height * 1000 * scale);
      ctx.fillStyle = '#8d96a8';
      for (const cyl of arena.cylinders) {
        ctx.beginPath(); ctx.arc(X(cyl.x * 1000), Y(cyl.y * 1000), cyl.radius * 1000 * scale, 0, 2 * Math.PI); ctx.fill();
      }
      for (const b of arena.boxes) {
        ctx.save(); ctx.translate(X(b.x * 1000), Y(b.y * 1000)); ctx.rotate(-b.angle);
        ctx.fillRect(-b.width * 500 * scale, -b.height * 500 * scale, b.width * 1000 * scale, b.height * 1000 * scale);
        ctx.restore();
      }
      // Segment walls (arenas stored before they existed have none): the rectangle of the
      // segment's length and the wall's thickness, its ends square.
      for (const w of arena.walls || []) {
        ctx.strokeStyle = '#8d96a8'; ctx.lineCap = 'butt';
        ctx.lineWidth = Math.max(1, w.thickness * 1000 * scale);
        ctx.beginPath(); ctx.moveTo(X(w.x1 * 1000), Y(w.y1 * 1000)); ctx.lineTo(X(w.x2 * 1000), Y(w.y2 * 1000)); ctx.stroke();
      }
      if (arena.goal) {
        const gx = X(arena.goal.x * 1000), gy = Y(arena.goal.y * 1000);
        ctx.strokeStyle = '#c51b7d'; ctx.fillStyle = '#c51b7d'; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.arc(gx, gy, 9, 0, 2 * Math.PI); ctx.stroke();
        ctx.beginPath(); ctx.arc(gx, gy, 3.5, 0, 2 * Math.PI); ctx.fill();
      }
      // Floor zones where they were in this epoch (random ones move at every epoch start;
      // replays stored by older versions lack their positions, and skip them), and lights.
      const placed = (c.replay.epoch_zones || [])[epoch] || [];
      const zoneAt = (i) => {
        const z = arena.zones[i];
        if (!z.random_position) return [z.x * 1000, z.y * 1000];
        return placed[i] || null;
      };
      (arena.zones || []).forEach((z, i) => {
        const at = zoneAt(i);
        if (!at) return;
        ctx.fillStyle = z.recharge ? 'rgba(44,160,44,0.18)' : (z.visible ? 'rgba(60,60,60,0.18)' : 'rgba(60,60,60,0.06)');
        ctx.strokeStyle = 'rgba(60,60,60,0.5)'; ctx.lineWidth = 1; ctx.setLineDash([4, 3]);
        ctx.beginPath();
        if (z.shape === 'circle') ctx.arc(X(at[0]), Y(at[1]), z.radius * 1000 * scale, 0, 2 * Math.PI);
        else ctx.rect(X(at[0] - z.width * 500), Y(at[1] + z.height * 500), z.width * 1000 * scale, z.height * 1000 * scale);
        ctx.fill(); ctx.stroke(); ctx.setLineDash([]);
      });
      for (const l of arena.lights || []) {
        const at = l.above_zone >= 0 ? zoneAt(l.above_zone) : [l.x * 1000, l.y * 1000];
        if (!at) continue;
        ctx.fillStyle = '#f2c12e'; ctx.strokeStyle = '#a67c00'; ctx.lineWidth = 1.5;
        ctx.beginPath(); ctx.arc(X(at[0]), Y(at[1]), 7, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      }
      if (energy !== undefined && energy < 1) {
        // The accumulator, as a bar in the arena's top left corner.
        ctx.fillStyle = '#ddd'; ctx.fillRect(8, 8, 60, 8);
        ctx.fillStyle = energy > 0.2 ? '#2ca02c' : '#d62728'; ctx.fillRect(8, 8, 60 * energy, 8);
        ctx.strokeStyle = '#555'; ctx.lineWidth = 1; ctx.strokeRect(8, 8, 60, 8);
      }
      // Each robot's trajectory in this epoch up to the current step (steps, not rows: a
      // group's step is `robots` rows).
      let start = index;
      while (start > 0 && rows[(start - 1) * robots][0] === epoch) --start;
      ctx.lineWidth = 2;
      for (let k = 0; k < robots; ++k) {
        for (let i = start + 1; i <= index; ++i) {
          const a = rows[(i - 1) * robots + k], b = rows[i * robots + k];
          ctx.strokeStyle = robots > 1 ? choiceColour(k, robots) : b[8] >= 0 ? choiceColour(b[8], c.actions.length) : '#1f77b4';
          ctx.beginPath(); ctx.moveTo(X(a[2]), Y(a[3])); ctx.lineTo(X(b[2]), Y(b[3])); ctx.stroke();
        }
      }
      ctx.fillStyle = collisionColour;
      for (let i = start * robots; i < (index + 1) * robots; ++i)
        if (rows[i][10]) { ctx.beginPath(); ctx.arc(X(rows[i][2]), Y(rows[i][3]), 3, 0, 2 * Math.PI); ctx.fill(); }
      for (let k = 0; k < robots; ++k) drawRobot(rows[index * robots + k], k);
      // A robot's body may have fewer than the group's widest (the rest shown empty).
      const mine = (values, count) => (count === undefined || Number.isNaN(count) ? values : values.slice(0, count));
      if (radarCount > 0) radars.show(mine(r[radarAt], shapeOf(watched).radars));
      if (rangeCount > 0) ranges.show(mine(r[rangeAt], shapeOf(watched).ranges));
      const own = shapeOf(watched).irMounts.length;
      irs.relabel(i => `${irName(robotBody[watched] ?? 0)} ${i}`);
      irs.show(ir.slice(0, own));
      // Replays stored before the light sensors were traced have none.
      lights.show((light || [0, 0, 0, 0, 0, 0, 0, 0]).slice(0, own));
      accumulator.show([energy === undefined ? 1 : energy]);
      action.textContent = act >= 0 ? (c.actions[act] || `action ${act}`) : 'wheels (classical head)';
      action.style.background = act >= 0 ? alpha(choiceColour(act, c.actions.length), 0.3) : '#e9eef8';
      readout.textContent =
        `epoch ${epoch + 1}, step ${step + 1}${robots > 1 ? `, robot ${watched + 1} of ${robots}` : ''}\n` +
        `position  x ${x.toFixed(1)} mm  y ${y.toFixed(1)} mm  heading ${(heading * 180 / Math.PI).toFixed(0)} deg\n` +
        `commands  left ${left.toFixed(2)}  right ${right.toFixed(2)}\n` +
        `fitness so far  ${fitness.toFixed(3)}${energy !== undefined && energy < 1 ? `\nenergy  ${energy.toFixed(2)}` : ''}${collided ? '\ncollision' : ''}`;
      slider.value = String(index);
    }
    function tick(time) {
      if (playing && last !== null) {
        carry += (time - last) / 100 * Number(speed.value);   // one control step is 100 ms
        const n = Math.floor(carry);
        if (n > 0) { carry -= n; index = (index + n) % (rows.length / robots); draw(); }
      }
      last = time;
      requestAnimationFrame(tick);
    }
    select.addEventListener('change', () => choose(Number(select.value)));
    play.addEventListener('click', () => { playing = !playing; play.textContent = playing ? 'Pause' : 'Play'; });
    slider.addEventListener('input', () => { index = Number(slider.value); draw(); });
    choose(0);
    requestAnimationFrame(tick);
  }

  function render() {
    root.innerHTML = '';
    for (const study of data.studies || []) root.appendChild(studySection(study));
    for (const exp of data.experiments) {
      const section = el('section');
      section.appendChild(el('h1', {text: exp.condition ?
        `Condition ${exp.condition} of study ${exp.study} (experiment ${exp.name})` : `Experiment ${exp.name}`}));
      const finished = exp.controllers.reduce((n, c) => n + c.runs.length, 0);
      const unfinished = exp.controllers.reduce((n, c) => n + c.unfinished_runs, 0);
      section.appendChild(el('p', {class: 'meta', text:
        `${counted(exp.controllers.length, 'controller')} × ${counted(exp.runs, 'run')} × ` +
        `${counted(exp.generations, 'generation')}, ${counted(exp.epochs, 'epoch')} × ${counted(exp.steps, 'step')}; ` +
        `seed ${exp.seed}; ${exp.status}` +
        (exp.status !== 'finished' ? ` (${counted(finished, 'run')} finished, ${unfinished} in progress)` : '') +
        `; script ${exp.script} (hash ${exp.content_hash}); esc ${exp.software_version}; started ${exp.created}` +
        (exp.directory ? `; directory ${exp.directory}` : '')}));
      section.appendChild(el('h2', {text: 'Fitness over generations'}));
      const figureGrid = el('div', {class: 'figures'});
      section.appendChild(figureGrid);
      figures(figureGrid, exp.figures);
      const curvesGrid = el('div', {class: 'grid'});
      section.appendChild(curvesGrid);
      fitnessChart(curvesGrid, exp, 'best', 'Best fitness of the generation');
      fitnessChart(curvesGrid, exp, 'mean', 'Mean fitness of the generation');
      section.appendChild(el('h2', {text: 'Final results and statistics'}));
      const statsGrid = el('div', {class: 'grid'});
      section.appendChild(statsGrid);
      boxChart(statsGrid, exp);
      statsTables(statsGrid, exp);
      const symbolic = exp.controllers.filter(c => c.actions.length > 0 && c.usage.length > 0);   // symbolic heads and supervisors
      if (symbolic.length > 0) {
        section.appendChild(el('h2', {text: 'Behavior usage'}));
        const usageGrid = el('div', {class: 'grid'});
        section.appendChild(usageGrid);
        symbolic.forEach(c => usageChart(usageGrid, c, palette[exp.controllers.indexOf(c) % palette.length]));
      }
      const overGenerations = exp.controllers.filter(c => c.usage_generations.some(r => r.best.some(g => g !== null)));
      if (overGenerations.length > 0) {
        section.appendChild(el('h2', {text: 'Behavior usage over generations'}));
        const grid = el('div', {class: 'grid'});
        section.appendChild(grid);
        overGenerations.forEach(c => usageOverGenerations(grid, c));
      }
      if (exp.controllers.some(c => c.transfers)) {
        section.appendChild(el('h2', {text: 'Generalization'}));
        transfersCard(section, exp);
      }
      const trees = exp.controllers.filter(c => c.runs.some(r => r.best_tree));   // tree controllers
      if (trees.length > 0) {
        section.appendChild(el('h2', {text: 'Best trees'}));
        const card = el('div', {class: 'card'});
        section.appendChild(card);
        for (const c of trees) {
          card.appendChild(el('h3', {text: `${c.name} (${c.architecture})`}));
          for (const r of c.runs)
            card.appendChild(el('p', {class: 'tree', text: `run ${r.run}, fitness ${fmt(r.best_fitness, fitnessDecimals(r.best_fitness, 1))}: ${r.best_tree}`}));
        }
      }
      section.appendChild(el('h2', {text: 'Replay'}));
      replay(section, exp);
      const settings = el('table');
      settings.appendChild(el('tr', {}, [el('th', {text: 'setting'}), el('th', {text: 'value'})]));
      for (const [k, v] of Object.entries(exp.settings))
        settings.appendChild(el('tr', {}, [el('td', {text: k}), el('td', {text: v})]));
      section.appendChild(el('h2', {text: 'Settings'}));
      section.appendChild(el('div', {class: 'card'}, [settings]));
      root.appendChild(section);
    }
    if (data.experiments.length === 0) root.appendChild(el('p', {text: 'No experiment stored.'}));
  }

  render();
  if (window.escErrors.length === 0) document.title += ' (ready)';
})();
