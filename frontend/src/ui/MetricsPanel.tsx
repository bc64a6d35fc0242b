import { FPS, useStudio } from "../store";
import bandsFile from "./metricBands.json";
import { BAND_WORDS, METRIC_ROWS, formatMetricValue, metricBand, metricTitle, type BandRule } from "./format";

/** Bands from real captures (frontend/scripts/metric_bands.py → metricBands.json). */
const BANDS = bandsFile.bands as Record<string, BandRule>;

/** Clip metrics of the current motion with units, a description on hover and a green / amber /
 * red band against real motion capture (interaction rows only for two people). */
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
        <>
          <dl className="metrics">
            {rows.map((r) => {
              const band = metricBand(metrics[r.key], BANDS[r.key]);
              return (
                <div className="metrics__row" key={r.key} title={metricTitle(r, BANDS[r.key])} data-testid={`metric-${r.key}`} data-band={band ?? ""}>
                  <dt>{r.label}</dt>
                  <dd>
                    {formatMetricValue(r, metrics[r.key], FPS)}
                    {band && <span className={`band band--${band}`} role="img" aria-label={BAND_WORDS[band]} title={BAND_WORDS[band]} />}
                  </dd>
                </div>
              );
            })}
          </dl>
          <p className="muted small metrics__key">
            <span className="band band--green" /> like real capture <span className="band band--amber" /> worse than 9 in 10{" "}
            <span className="band band--red" /> worse than 99 in 100 · hover a row for what it measures
          </p>
        </>
      )}
    </section>
  );
}
