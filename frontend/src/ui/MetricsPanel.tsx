import { useStudio } from "../store";
import { METRIC_ROWS, formatMetric } from "./format";

/** Clip metrics of the current motion (interaction rows only for two people). */
export function MetricsPanel() {
  const metrics = useStudio((s) => s.stream.metrics);
  const persons = useStudio((s) => s.motionPersons);
  const rows = METRIC_ROWS.filter((r) => !r.pair || persons === 2);
  return (
    <section className="panel" aria-labelledby="metrics-title" data-testid="metrics">
      <h2 id="metrics-title">Metrics</h2>
      {!metrics ? (
        <p className="muted small">Metrics appear when a motion is done.</p>
      ) : (
        <dl className="metrics">
          {rows.map((r) => (
            <div className="metrics__row" key={r.key} title={r.hint} data-testid={`metric-${r.key}`}>
              <dt>{r.label}</dt>
              <dd>{formatMetric(metrics[r.key])}</dd>
            </div>
          ))}
        </dl>
      )}
    </section>
  );
}
