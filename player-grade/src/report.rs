//! What the grader writes for people and for other tools: each submission's `results.json` in
//! Gradescope's autograder format, and for the class `summary.csv`, `junit.xml` (for CI
//! dashboards) and `report.html` (one row per student: score, each check, the picture).

use std::fmt::Write as _;
use std::path::Path;

use serde_json::{Value, json};

use crate::graded::Graded;
use crate::spec::Spec;

/// Gradescope's `results.json`: the score, the run's time, the output a student sees (how the
/// run ended, the error, the program's last lines) and one test per check.
pub fn results_json(spec: &Spec, graded: &Graded) -> Value {
    let tests: Vec<Value> = graded
        .verdicts
        .iter()
        .enumerate()
        .map(|(i, v)| {
            json!({
                "name": v.name,
                "number": (i + 1).to_string(),
                "score": v.score,
                "max_score": v.max_score,
                "status": if v.passed() { "passed" } else { "failed" },
                "output": v.output,
                "visibility": "visible",
            })
        })
        .collect();
    json!({
        "score": graded.score,
        "execution_time": graded.wall.as_secs_f64().round(),
        "output": student_output(graded),
        "visibility": "visible",
        "stdout_visibility": "visible",
        "tests": tests,
        "extra_data": {
            "max_score": spec.max_score(),
            "simulated_seconds": graded.simulated,
            "world": spec.world.file_name().map(|n| n.to_string_lossy().into_owned()),
            "seed": spec.seed,
            "notes": graded.notes,
        },
    })
}

/// What the student reads: how the run ended, its error, notes, then their program's output.
pub fn student_output(graded: &Graded) -> String {
    let mut out = format!("The run {}.\n", graded.ended);
    if let Some(error) = &graded.error {
        let _ = writeln!(out, "Error: {error}");
    }
    for note in &graded.notes {
        let _ = writeln!(out, "Note: {note}.");
    }
    if graded.output.trim().is_empty() {
        out.push_str("\nThe program printed nothing.\n");
    } else {
        let _ = write!(out, "\nThe program's last lines:\n{}", graded.output);
    }
    out
}

/// One row per submission: name, score, max, each check's score, how the run ended.
pub fn summary_csv(spec: &Spec, class: &[Graded]) -> String {
    let mut out = String::from("name,score,max_score");
    for check in &spec.checks {
        out.push(',');
        out.push_str(&csv_field(&check.name));
    }
    out.push_str(",ended\n");
    for graded in class {
        let _ = write!(
            out,
            "{},{},{}",
            csv_field(&graded.name),
            number(graded.score),
            number(graded.max_score)
        );
        for verdict in &graded.verdicts {
            let _ = write!(out, ",{}", number(verdict.score));
        }
        let _ = writeln!(out, ",{}", csv_field(&graded.ended));
    }
    out
}

/// A JUnit report: a test suite of the class, a test case per submission and check.
pub fn junit_xml(spec: &Spec, class: &[Graded]) -> String {
    let cases: usize = class.iter().map(|g| g.verdicts.len()).sum();
    let failures: usize = class
        .iter()
        .flat_map(|g| &g.verdicts)
        .filter(|v| !v.passed())
        .count();
    let seconds: f64 = class.iter().map(|g| g.wall.as_secs_f64()).sum();
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        out,
        "<testsuites name=\"{}\" tests=\"{cases}\" failures=\"{failures}\" time=\"{seconds:.3}\">",
        xml(&spec.path.display().to_string())
    );
    for graded in class {
        let failed = graded.verdicts.iter().filter(|v| !v.passed()).count();
        let _ = writeln!(
            out,
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{failed}\" time=\"{:.3}\">",
            xml(&graded.name),
            graded.verdicts.len(),
            graded.wall.as_secs_f64()
        );
        for verdict in &graded.verdicts {
            let _ = write!(
                out,
                "    <testcase classname=\"{}\" name=\"{}\"",
                xml(&graded.name),
                xml(&verdict.name)
            );
            if verdict.passed() {
                let _ = writeln!(out, "/>");
            } else {
                let _ = writeln!(
                    out,
                    ">\n      <failure message=\"{}\">{} of {} points</failure>\n    </testcase>",
                    xml(&verdict.output),
                    number(verdict.score),
                    number(verdict.max_score)
                );
            }
        }
        let _ = writeln!(
            out,
            "    <system-out>{}</system-out>\n  </testsuite>",
            xml(&crate::report::student_output(graded))
        );
    }
    out.push_str("</testsuites>\n");
    out
}

/// The class on one page: a row per student, the checks as columns, the picture of each run.
pub fn report_html(spec: &Spec, class: &[Graded], out_dir: &Path) -> String {
    let mut page = String::new();
    let title = format!("Grades: {}", spec.path.display());
    let _ = write!(
        page,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title>\n<style>{STYLE}</style></head><body>\n<h1>{}</h1>\n",
        xml(&title),
        xml(&title)
    );
    let total: f64 = class.iter().map(|g| g.score).sum();
    let mean = if class.is_empty() {
        0.0
    } else {
        total / class.len() as f64
    };
    let _ = writeln!(
        page,
        "<p class=\"about\">World <b>{}</b>, robot <b>{}</b>, {} s simulated, seed {}, {}. \
         {} submissions, mean score {} of {}.</p>",
        xml(&spec.world.file_name().unwrap_or_default().to_string_lossy()),
        xml(&spec.robot),
        spec.time_limit,
        spec.seed,
        if spec.lockstep {
            "lockstep"
        } else {
            "real time"
        },
        class.len(),
        number(mean),
        number(spec.max_score())
    );
    page.push_str("<table>\n<thead><tr><th>Student</th><th>Score</th>");
    for check in &spec.checks {
        let _ = write!(
            page,
            "<th>{} <span class=\"max\">({})</span></th>",
            xml(&check.name),
            number(check.points)
        );
    }
    page.push_str("<th>Run</th><th>Path</th></tr></thead>\n<tbody>\n");
    for graded in class {
        let folder = graded
            .folder
            .strip_prefix(out_dir)
            .unwrap_or(&graded.folder)
            .display()
            .to_string();
        let _ = write!(
            page,
            "<tr><td class=\"name\">{}</td><td class=\"score\">{} / {}</td>",
            xml(&graded.name),
            number(graded.score),
            number(graded.max_score)
        );
        for verdict in &graded.verdicts {
            let class = if verdict.passed() { "pass" } else { "fail" };
            let _ = write!(
                page,
                "<td class=\"{class}\" title=\"{}\">{}<div class=\"why\">{}</div></td>",
                xml(&verdict.output),
                number(verdict.score),
                xml(&verdict.output)
            );
        }
        let mut run = xml(&graded.ended);
        if let Some(error) = &graded.error {
            let _ = write!(run, "<div class=\"error\">{}</div>", xml(error));
        }
        for note in &graded.notes {
            let _ = write!(run, "<div class=\"note\">{}</div>", xml(note));
        }
        let _ = write!(
            run,
            "<div class=\"files\"><a href=\"{f}/results.json\">results.json</a> · \
             <a href=\"{f}/run.mcap\">run.mcap</a></div>",
            f = xml(&folder)
        );
        let _ = writeln!(
            page,
            "<td class=\"run\">{run}</td><td><a href=\"{f}/path.png\"><img src=\"{f}/path.png\" \
             alt=\"the path of {}\" width=\"240\"></a></td></tr>",
            xml(&graded.name),
            f = xml(&folder)
        );
    }
    page.push_str("</tbody></table>\n</body></html>\n");
    page
}

const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}\
h1{font-size:1.4em}.about{color:#555}table{border-collapse:collapse}\
th,td{border:1px solid #ddd;padding:.4em .6em;vertical-align:top;text-align:left}\
th{background:#f3f3f0}.max{color:#888;font-weight:normal}.name{font-weight:bold}\
.score{font-size:1.2em;white-space:nowrap}.pass{background:#e6f4ea}.fail{background:#fbe9e7}\
.why{font-size:.8em;color:#555;max-width:14em}.error{color:#b00020;font-family:monospace;font-size:.85em}\
.note{color:#8a5a00;font-size:.85em}.files{font-size:.8em;margin-top:.4em}.run{max-width:18em}";

/// A score as people write it: no trailing `.0`, at most two decimals.
fn number(x: f64) -> String {
    let rounded = (x * 100.0).round() / 100.0;
    if rounded.fract() == 0.0 {
        format!("{rounded:.0}")
    } else {
        format!("{rounded}")
    }
}

fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// Text for XML and HTML, in an attribute or an element.
fn xml(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c if c.is_control() && c != '\n' && c != '\t' => out.push('\u{fffd}'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped_for_each_format() {
        assert_eq!(
            xml("a<b & \"c\"\u{7}"),
            "a&lt;b &amp; &quot;c&quot;\u{fffd}"
        );
        assert_eq!(csv_field("plain"), "plain");
        assert_eq!(csv_field("a, \"b\""), "\"a, \"\"b\"\"\"");
        assert_eq!(number(60.0), "60");
        assert_eq!(number(33.333), "33.33");
    }
}
