import { plainError } from "../api/formCheck";
import { useStudio } from "../store";
import { FormProblems } from "./FormProblems";

/** The prompt form's own problems, then the last error (the API's `detail` message, or a
 * stream's, in plain sentences: api/formCheck.ts), dismissible. */
export function ErrorBanner() {
  const error = useStudio((s) => s.error);
  const setError = useStudio((s) => s.setError);
  return (
    <>
      <FormProblems />
      {error && (
        <div className="error-banner" role="alert" data-testid="error-banner">
          <span className="error-banner__icon" aria-hidden>
            !
          </span>
          <span className="error-banner__text">{plainError(error)}</span>
          <button className="icon-button" onClick={() => setError(null)} aria-label="Dismiss error">
            ×
          </button>
        </div>
      )}
    </>
  );
}
