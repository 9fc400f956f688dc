;; Three pieces lie about the table: build a tower on the dock pad, the
;; block at the bottom, the drum on the block, the cap on the drum.
(define (problem blind11-p05)
  (:domain blind11-stack)
  (:objects block drum cap - piece
            mat-a mat-b mat-c dock - pad)
  (:init (sits block mat-a) (sits drum mat-b) (sits cap mat-c)
         (bare block) (bare drum) (bare cap) (idle))
  (:goal (and (sits block dock) (perched drum block) (perched cap drum)
              (idle))))
