; blind20 p01: a pen (15 x 3 x 3 cm) and a ruler (20 x 3 x 3 cm) must each
; be stored in a container. The square case (13.6 cm, rimmed) takes the
; pen only along a diagonal (45 +- 4.8 deg; 41.7-48.3 with the rims' 1 mm);
; the ruler fits it at no yaw (a proof before any NLP). The tray
; (26 x 8 cm) takes either. Cheapest (4): pen -> case, ruler -> tray.
(define (problem p01)
  (:domain pen-case)
  (:objects pen ruler - item
            pen-home ruler-home - spot
            case tray - container)
  (:init (at pen pen-home) (at ruler ruler-home)
         (free case) (free tray) (handempty))
  (:goal (forall (?i - item) (exists (?c - container) (at ?i ?c)))))
